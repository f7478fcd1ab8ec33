// One headless GL context, renderer and glyph cache for a whole test program,
// made on first use: the context must exist before any DrawBatch uploads, and
// making one per test would dominate the GL tests' time.
#pragma once

#include "curvetext/headless.hpp"
#include "curvetext/renderer.hpp"

namespace curvetext::test {

struct Gpu {
  HeadlessContext context = HeadlessContext::create();
  Renderer renderer;
  GlyphCache cache;
};

Gpu& gpu();

}  // namespace curvetext::test
