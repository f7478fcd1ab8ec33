// Threads (the thread-safety notes of the public headers): objects that are
// not shared may be used on distinct threads, each with its own GL context.
// Two threads draw at once and must get the images one thread gets alone.
// scripts/test-sanitize.sh also builds this under ThreadSanitizer, which
// reports any data race between them in the library (such as a shared
// counter written without synchronisation).
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"
#include "support/fonts.hpp"

namespace curvetext {
namespace {

// Everything one thread needs, made on that thread: context, font, cache,
// renderer. Draws `text` in `rounds` fresh blocks (each new block takes a
// serial number) and returns the last image of each mode.
std::vector<Image> draw_alone(const std::string& text, int rounds) {
  HeadlessContext context = HeadlessContext::create();
  const Font font = Font::open(test::kDejaVuSans);
  GlyphCache cache;
  Renderer renderer;
  ImageTarget target;
  const ShapedLine line = shape_line(font, text);
  const double ppem = 20.0, scale = ppem / font.metrics().units_per_em;
  std::vector<Image> images;
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Curves, AntiAliasing::Vbaa}) {
    Image last;
    for (int i = 0; i < rounds; ++i) {
      const DrawBatch batch = DrawBatch::from_text(cache, font, line, ppem);
      target.begin(260, 32, Color{1, 1, 1, 1});
      renderer.draw(batch, Placement(scale, 4.25, 24.5), DrawOptions(Color{0, 0, 0, 1}, aa));
      last = target.read_pixels();
    }
    images.push_back(std::move(last));
  }
  return images;
}

TEST(Threads, TwoThreadsWithTwoContextsDrawAsOneAlone) {
  const std::string texts[2] = {"The first thread's text", "and the second one's"};
  std::vector<Image> alone[2];
  for (int t = 0; t < 2; ++t) alone[t] = draw_alone(texts[t], 1);

  std::vector<Image> together[2];
  std::string errors[2];
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t) {
    threads.emplace_back([&, t] {
      try {
        together[t] = draw_alone(texts[t], 6);
      } catch (const Error& e) {
        errors[t] = e.what();
      }
    });
  }
  for (std::thread& th : threads) th.join();
  for (int t = 0; t < 2; ++t) {
    ASSERT_EQ(errors[t], "") << "thread " << t;
    ASSERT_EQ(together[t].size(), alone[t].size());
    for (std::size_t m = 0; m < alone[t].size(); ++m) {
      EXPECT_EQ(together[t][m].rgba, alone[t][m].rgba) << "thread " << t << ", mode " << m;
      std::size_t dark = 0;
      for (std::size_t i = 0; i < alone[t][m].rgba.size(); i += 4) dark += alone[t][m].rgba[i] < 128;
      EXPECT_GT(dark, 150u) << "thread " << t << " drew nothing in mode " << m;
    }
  }
}

}  // namespace
}  // namespace curvetext
