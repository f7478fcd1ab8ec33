#include "support/gpu.hpp"

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

namespace curvetext::test {

ContextKind test_context_kind() {
  const char* name = std::getenv("CURVETEXT_TEST_CONTEXT");
  const std::string kind = name != nullptr ? name : "gles2";
  if (kind == "gles2") return ContextKind::Gles2;
  if (kind == "gles3") return ContextKind::Gles3;
  if (kind == "gl-core") return ContextKind::GlCore;
  if (kind == "gl-compat") return ContextKind::GlCompat;
  throw std::invalid_argument("CURVETEXT_TEST_CONTEXT: unknown context kind " + kind);
}

bool expects_gles2() {
  const char* v = std::getenv("MESA_GLES_VERSION_OVERRIDE");
  return v != nullptr && std::string(v) == "2.0";
}

Gpu& gpu() {
  static std::unique_ptr<Gpu> instance = std::make_unique<Gpu>();
  return *instance;
}

}  // namespace curvetext::test
