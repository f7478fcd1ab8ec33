// Draws one line of text with curvetext: the part an application runs in its
// own GL context, then the same into a headless context, written to a PNG.
//
//   hello_png [FONT_FILE] [OUT.png] [TEXT]
#include <cmath>
#include <cstdio>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/image.hpp"
#include "curvetext/image_target.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"

using namespace curvetext;

// Needs a current GL context (GLES2 or later, or desktop GL 3.3). draw()
// renders into the framebuffer and viewport bound now and leaves the GL state
// as it found it: font units (y up) become pixels (y down, from the
// viewport's top left) as x_px = scale * x + origin_x, y_px = origin_y -
// scale * y, so (origin_x, origin_y) is the pen's start on the baseline. An
// application that draws the same text every frame keeps the DrawBatch and
// calls only renderer.draw() per frame.
void draw_line(Renderer& renderer, GlyphCache& cache, const Font& font, const std::string& text, double size_px,
               double x, double baseline_y) {
  const ShapedLine line = shape_line(font, text);                            // HarfBuzz, font units
  const DrawBatch batch = DrawBatch::from_text(cache, font, line, size_px);  // meshes cached per glyph
  const double scale = size_px / font.metrics().units_per_em;
  renderer.draw(batch, Placement(scale, x, baseline_y), DrawOptions(Color{0.1f, 0.1f, 0.3f, 1.0f}));
}

int main(int argc, char** argv) {
  const std::string font_path = argc > 1 ? argv[1] : "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  const std::string out_path = argc > 2 ? argv[2] : "hello.png";
  const std::string text = argc > 3 ? argv[3] : "Hello, world";
  try {
    const Font font = Font::open(font_path);
    const double size_px = 48.0, margin = 16.0;
    const FontMetrics m = font.metrics();
    const double scale = size_px / m.units_per_em;
    const int width = static_cast<int>(std::ceil(2 * margin + shape_line(font, text).advance * scale));
    const int height = static_cast<int>(std::ceil(2 * margin + (m.ascender - m.descender) * scale));

    // No window here: an EGL context of our own (Mesa's llvmpipe without a GPU).
    HeadlessContext context = HeadlessContext::create();
    Renderer renderer;   // of the current context; compiles each mode's shaders on first use
    ImageTarget target;  // an offscreen image to draw into
    GlyphCache cache;    // glyph meshes, built once per glyph and reused
    target.begin(width, height, Color{1, 1, 1, 1});  // an offscreen framebuffer, cleared
    draw_line(renderer, cache, font, text, size_px, margin, margin + m.ascender * scale);
    write_png(target.read_pixels(), out_path);
    std::printf("wrote %s (%dx%d)\n", out_path.c_str(), width, height);
  } catch (const Error& e) {
    std::fprintf(stderr, "hello_png: %s\n", e.what());
    return 1;
  }
  return 0;
}
