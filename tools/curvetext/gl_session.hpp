// The CLI's GL context, renderer and glyph cache.
#pragma once

#include "curvetext/headless.hpp"
#include "curvetext/renderer.hpp"

namespace curvetext::cli {

struct GlSession {
  HeadlessContext context = HeadlessContext::create();
  Renderer renderer;
  GlyphCache cache;
};

// Made on first use (throws Error(NoDevice) or Error(Gl) as HeadlessContext
// and Renderer do) and never destroyed: tearing the driver's context down
// (llvmpipe freeing its JIT code and joining its threads) costs more than
// drawing a short text, just before the process ends and frees it all anyway.
GlSession& gl_session();

}  // namespace curvetext::cli
