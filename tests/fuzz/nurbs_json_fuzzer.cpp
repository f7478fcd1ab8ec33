// NURBS JSON shape documents (docs/shapes/README.md) -> outlines -> meshes,
// as `curvetext shape` does before drawing, without GL.
#include "curvetext/shapes.hpp"
#include "shape_meshes.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvetext;
  ShapeDocument doc;
  try {
    doc = parse_shape_json(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const Error&) {
    return 0;
  }
  fuzz::shape_meshes(doc);
  return 0;
}
