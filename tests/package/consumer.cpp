// A program using curvetext the way another project would, through the
// installed headers and library only (tests/package/consumer_test.sh).
//   consumer OUT.png       opens the default font, shapes and renders a line,
//                          checks that curvetext::Error crosses the library
//   consumer --default-font  prints the default font's path, or the error
//                          (exit status 3)
#include <cstdio>
#include <cstring>
#include <string>

#include "curvetext/default_font.hpp"
#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/image.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/text_image.hpp"
#include "curvetext/version.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fputs("usage: consumer OUT.png | --default-font\n", stderr);
    return 2;
  }
  if (std::strcmp(argv[1], "--default-font") == 0) {
    try {
      std::printf("default font: %s\n", curvetext::default_font_path().c_str());
      return 0;
    } catch (const curvetext::Error& e) {
      std::printf("error (%s): %s\n", curvetext::to_string(e.code()), e.what());
      return 3;
    }
  }
  try {
    std::printf("curvetext %s (headers %s)\n", curvetext::version(), CURVETEXT_VERSION_STRING);
    if (std::strcmp(curvetext::version(), CURVETEXT_VERSION_STRING) != 0) return 1;

    const std::string path = curvetext::default_font_path();
    const curvetext::Font font = curvetext::Font::open(path);
    const char* text = "Hello, curvetext";
    const curvetext::ShapedLine line = curvetext::shape_line(font, text);
    std::printf("default font: %s (%s), \"%s\": %zu glyphs\n", path.c_str(), font.family_name().c_str(), text,
                line.glyphs.size());
    if (line.glyphs.size() != std::strlen(text)) return 1;

    // The library's exception type must be the program's.
    try {
      (void)curvetext::Font::open("/nonexistent/font.ttf");
      return 1;
    } catch (const curvetext::Error& e) {
      if (e.code() != curvetext::ErrorCode::FontNotFound) return 1;
    }

    curvetext::HeadlessContext context = curvetext::HeadlessContext::create();
    curvetext::Renderer renderer;
    curvetext::GlyphCache cache;
    curvetext::TextImageOptions options;
    options.size_px = 24.0;
    const curvetext::TextImageLayout layout = curvetext::layout_text_image(font, text, options);
    const curvetext::Image image = curvetext::render_text_image(renderer, cache, font, layout, options);
    curvetext::write_png(image, argv[1]);
    std::size_t inked = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) inked += image.rgba[i] < 128;
    std::printf("rendered %dx%d on %s, %zu dark pixels -> %s\n", image.width, image.height, context.renderer().c_str(),
                inked, argv[1]);
    return inked > 0 ? 0 : 1;
  } catch (const curvetext::Error& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
