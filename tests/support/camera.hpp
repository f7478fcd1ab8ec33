// A 3D camera for the tests of text on a plane (transform_test, depth_test).
#pragma once

#include <array>

namespace curvetext::test {

// A column-major model-view-projection (as glm builds one): a camera 6 units
// from the plane z = 0, looking at (1, 0.5, 0) from above and to the side,
// a 50 degree vertical field of view, near and far planes 0.1 and 100.
std::array<float, 16> camera_mvp(double aspect);

}  // namespace curvetext::test
