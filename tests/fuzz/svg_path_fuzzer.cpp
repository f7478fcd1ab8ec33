// SVG path data (the d attribute) -> contours -> outline (nonzero or
// even-odd) -> mesh. The first byte picks the fill rule and the tolerance.
#include <cmath>

#include "curvetext/shapes.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvetext;
  fuzz::Input in(data, size);
  const std::uint8_t mode = in.byte();
  Shape shape;
  shape.fill_rule = mode & 1 ? FillRule::EvenOdd : FillRule::NonZero;
  // 1/16 down to 2^-15 document units.
  const double tolerance = std::ldexp(1.0, -4 - (mode >> 1) % 12);
  try {
    shape.contours = parse_svg_path(in.rest());
  } catch (const Error&) {
    return 0;
  }
  Outline outline;
  try {
    outline = fill_outline(shape, tolerance);
  } catch (const Error&) {
    return 0;
  }
  fuzz::mesh_and_check(outline, tolerance, true);
  return 0;
}
