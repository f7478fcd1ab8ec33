#include "common/world.hpp"

#include <cmath>

#include <glm/gtc/type_ptr.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace example {

namespace {

constexpr const char* kLabel = "curvetext";
constexpr double kLabelEm = 1.6;       // world units per em
constexpr double kSignPadding = 0.35;  // world units around the text
constexpr curvetext::Color kLabelColor{0.10f, 0.10f, 0.16f, 1.0f};

}  // namespace

glm::mat4 camera_at(int frame, int width, int height) {
  const float t = static_cast<float>(frame) / 60.0f;  // "seconds" at 60 frames a second
  const glm::vec3 target(1.5f * std::sin(0.7f * t), 0.8f * std::sin(0.45f * t), 0.0f);  // pans
  const float distance = 13.5f + 3.0f * std::sin(0.9f * t);                             // zooms
  const float yaw = glm::radians(-18.0f + 30.0f * std::sin(0.5f * t + 0.6f));           // rotates
  const float pitch = glm::radians(52.0f);                                              // above the plane
  // From the south-west (-y) of the target, looking north and down: the
  // board's +y is up on screen, so the label reads upright.
  const glm::vec3 eye =
      target + distance * glm::vec3(std::cos(pitch) * std::sin(yaw), -std::cos(pitch) * std::cos(yaw), std::sin(pitch));
  const glm::mat4 view = glm::lookAt(eye, target, glm::vec3(0.0f, 0.0f, 1.0f));
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  return glm::perspective(glm::radians(45.0f), aspect, 0.1f, 100.0f) * view;
}

WorldLabel world_label(std::shared_ptr<const curvetext::Font> font) {
  const curvetext::FontMetrics m = font->metrics();
  const double scale = kLabelEm / m.units_per_em;  // world units per font unit
  const double width = line_width(*font, kLabel, kLabelEm);
  // Centred on the world origin: the baseline a third of an em below it. As
  // a line at (x0, -baseline_y) with kLabelEm "pixels" per em, its Placement
  // maps font units to the plane's (x, -y).
  const double x0 = -width / 2.0, baseline_y = -kLabelEm / 3.0;
  WorldLabel label;
  // pixels_per_em only picks a level of detail; TrueType outlines have no
  // cubics, so one mesh serves every size the camera shows.
  label.text = line_item(std::move(font), kLabel, kLabelEm, x0, -baseline_y, kLabelColor);
  label.text.pixels_per_em = 64.0;
  const double top = baseline_y + m.ascender * scale, bottom = baseline_y + m.descender * scale;
  label.sign_min = glm::vec2(x0 - kSignPadding, bottom - kSignPadding);
  label.sign_max = glm::vec2(x0 + width + kSignPadding, top + kSignPadding);
  return label;
}

curvetext::Placement label_placement(const WorldLabel& label, const glm::mat4& view_projection, int width, int height) {
  // On the plane, depth-tested; on_plane's depth offset keeps the label in
  // front of the sign it lies on (drawn with glPolygonOffset(-1, -1), which
  // pulls the sign forward by less).
  const curvetext::Placement& at = label.text.placement;
  return curvetext::Placement::on_plane(glm::value_ptr(view_projection), width, height, at.scale, at.origin_x,
                                        -at.origin_y);
}

}  // namespace example
