// SVG documents -> shapes -> outlines -> meshes, as `curvetext shape` does
// before drawing (lib/compose/shape_image.cpp), without GL.
#include "curvetext/shape_image.hpp"
#include "curvetext/shapes.hpp"
#include "shape_meshes.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvetext;
  ShapeDocument doc;
  try {
    doc = parse_svg(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const Error&) {
    return 0;
  }
  fuzz::shape_meshes(doc);
  return 0;
}
