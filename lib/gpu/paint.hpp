// Private to the library: the gradient paint's uniforms in the composite
// pass (shaders/composite.frag.glsl with CURVETEXT_PAINT).
#pragma once

#include <GLES3/gl3.h>

#include "curvetext/image_target.hpp"
#include "curvetext/paint.hpp"
#include "curvetext/transform.hpp"

namespace curvetext::gpu {

struct PaintUniforms {
  GLint paint = -1, kind = -1, spread = -1, a = -1, b = -1, radius = -1, focal_radius = -1, count = -1, stop_color = -1,
        stop_offset = -1;
  static PaintUniforms of(GLuint program);
  // Sets the gradient for a pass whose outline units reach the framebuffer
  // through `full` (outline units -> pixels), with colours premultiplied in
  // the target's `blending`.
  void set(const Gradient& gradient, const Transform& full, Blending blending) const;
};

// The inverse of a projective map (the adjugate over the determinant).
Transform inverse(const Transform& t);

}  // namespace curvetext::gpu
