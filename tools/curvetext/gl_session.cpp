#include "gl_session.hpp"

namespace curvetext::cli {

GlSession& gl_session() {
  // Reachable from a static until exit, so leak checkers do not count it.
  static GlSession* session = new GlSession;
  return *session;
}

}  // namespace curvetext::cli
