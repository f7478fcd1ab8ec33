// One headless GL context, renderer and glyph cache for a whole test program,
// made on first use: the context must exist before any DrawBatch uploads, and
// making one per test would dominate the GL tests' time.
#pragma once

#include "curvetext/headless.hpp"
#include "curvetext/renderer.hpp"

namespace curvetext::test {

// The context kind of the GL tests: CURVETEXT_TEST_CONTEXT=gles2 (default),
// gles3, gl-core or gl-compat (tests/CMakeLists.txt runs them in several).
ContextKind test_context_kind();
// Whether this run asked Mesa for OpenGL ES 2.0 (MESA_GLES_VERSION_OVERRIDE=2.0,
// as tests/CMakeLists.txt does for the "gles2." runs): the tests then check
// that they really got it.
bool expects_gles2();

struct Gpu {
  HeadlessContext context = HeadlessContext::create(test_context_kind());
  Renderer renderer;
  ImageTarget target;  // the tests draw into offscreen images
  GlyphCache cache;
};

Gpu& gpu();

}  // namespace curvetext::test
