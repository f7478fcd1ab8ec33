// Raw outlines with extreme values -> build_mesh -> the mesh's invariants.
// The input is a list of path operations whose coordinates, weights and
// cubic tolerance may be anything (fuzz_support.hpp's Input::number: grid
// points, sixteenths, subnormal to huge magnitudes, NaN and infinities).
#include "fuzz_support.hpp"

namespace {

constexpr int kMaxOperations = 256;  // keeps each input's work small

curvetext::Vec2 point(curvetext::fuzz::Input& in) {
  const double x = in.number();
  return {x, in.number()};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvetext;
  fuzz::Input in(data, size);
  const std::uint8_t mode = in.byte();
  // Mostly the default tolerance; sometimes any number (0, negative, NaN).
  const double tolerance = mode & 1 ? in.number() : MeshOptions{}.cubic_tolerance;
  Outline outline;
  for (int op = 0; op < kMaxOperations && !in.empty(); ++op) {
    switch (in.byte() % 6) {
      case 0:
        outline.move_to(point(in));
        break;
      case 1:
      case 2:
        outline.line_to(point(in));
        break;
      case 3: {
        const Vec2 control = point(in), end = point(in);
        // A parabola unless the input asks for another weight.
        outline.conic_to(control, end, in.byte() & 1 ? in.number() : 1.0);
        break;
      }
      case 4: {
        const Vec2 c1 = point(in), c2 = point(in), end = point(in);
        outline.cubic_to(c1, c2, end);
        break;
      }
      default:
        outline.close();
    }
  }
  outline.close();
  // The invariants hold for any input build_mesh accepts; (mode & 2) skips
  // the full check to explore faster.
  fuzz::mesh_and_check(outline, tolerance, !(mode & 2));
  return 0;
}
