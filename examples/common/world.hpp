// The world of the GLFW example: a board on the plane z = 0 seen by a GLM
// camera that pans, zooms and rotates with the frame number, and a text label
// lying on the board. Shared with the screenshot checker.
#pragma once

#include <memory>

#include <glm/glm.hpp>

#include "curvetext/font.hpp"
#include "curvetext/transform.hpp"
#include "common/text.hpp"

namespace example {

// The camera's view-projection matrix at `frame` (the animation follows the
// frame number, not the clock, so a frame is the same on every run).
glm::mat4 camera_at(int frame, int width, int height);

// The label lying on the board: its text as placed glyphs, with a Placement
// from font units to the world plane (x, -y) that the caller completes with
// Transform::plane_to_viewport (label_placement), and the sign under it (world
// units).
struct WorldLabel {
  TextItem text;       // placement.transform: identity until drawn
  glm::vec2 sign_min;  // the sign's corners on the plane
  glm::vec2 sign_max;
};
WorldLabel world_label(std::shared_ptr<const curvetext::Font> font);

// The label's Placement for this frame's camera.
curvetext::Placement label_placement(const WorldLabel& label, const glm::mat4& view_projection, int width, int height);

}  // namespace example
