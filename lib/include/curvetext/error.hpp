// curvetext's one error model: every failure the caller can act on is thrown as
// curvetext::Error, carrying a code and a one-line message that names the
// problem (and the offending file or value). Nothing in the library aborts on
// bad input; programming errors inside the library are not reported this way.
#pragma once

#include <stdexcept>
#include <string>

#include "curvetext/export.hpp"

namespace curvetext {

enum class ErrorCode {
  InvalidArgument,  // a value outside its documented range (size <= 0, NaN, ...)
  InvalidText,      // text that is empty where text is required, or not valid UTF-8
  FontNotFound,     // the font file does not exist or cannot be read
  FontInvalid,      // the file is not a font FreeType/HarfBuzz can use, bad face index, bad axis
  Geometry,         // an outline the tessellator cannot turn into a valid mesh
  NoDevice,         // no EGL display / GLES2 context could be created
  Gl,               // a GL call failed (shader compile, framebuffer incomplete, ...)
  Io,               // writing an output file failed
};

// A short description of the code ("invalid argument", "font not found",
// ...): a static string, never null.
CURVETEXT_API const char* to_string(ErrorCode code) noexcept;

// what() is the message.
class CURVETEXT_API Error : public std::runtime_error {
 public:
  Error(ErrorCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  ErrorCode code() const noexcept { return code_; }

 private:
  ErrorCode code_;
};

}  // namespace curvetext
