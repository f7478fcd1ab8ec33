#include "curvetext/error.hpp"

namespace curvetext {

const char* to_string(ErrorCode code) noexcept {
  switch (code) {
    case ErrorCode::InvalidArgument:
      return "invalid argument";
    case ErrorCode::InvalidText:
      return "invalid text";
    case ErrorCode::FontNotFound:
      return "font not found";
    case ErrorCode::FontInvalid:
      return "invalid font";
    case ErrorCode::Geometry:
      return "invalid geometry";
    case ErrorCode::NoDevice:
      return "no GL device";
    case ErrorCode::Gl:
      return "GL error";
    case ErrorCode::Io:
      return "I/O error";
  }
  return "error";
}

}  // namespace curvetext
