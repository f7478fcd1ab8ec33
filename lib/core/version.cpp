#include "curvetext/version.hpp"

namespace curvetext {

const char* version() noexcept { return CURVETEXT_VERSION_STRING; }

}  // namespace curvetext
