// Checks a screenshot of an example app (examples/) against the same frame
// drawn with --no-text and against the exact coverage of the frame's text:
//
//  1. The app's own scene is intact: wherever no text lies (the exact
//     coverage of every text item, grown by kInkMarginPx), the screenshot
//     equals the --no-text one within kSceneLevels per channel.
//  2. The text is where the app placed it: per item, the coverage seen in the
//     screenshot, (shot - background) / (colour - background) with the
//     --no-text screenshot as background, is compared with the exact area
//     coverage of the item's glyph outlines (tests/support/union_coverage)
//     mapped by the item's Placement, perspective included. Limits:
//     kEdgeMeanLimit, kMaxLimit and kInkLimit below.
//
// The items (text, font, size, colour, placement) come from the examples'
// own code (examples/common), with the frame number and the HUD strings the
// app recorded next to its screenshot; the world camera's plane transform is
// checked against glm's own projection of points.
//
//   check_example_screenshot --scene world|hud --text SHOT.png --no-text SHOT.png
//                            --out DIR [--expect-gl TEXT]
//
// Exits 0 when every check passes, 1 otherwise (writing DIR/<name>-expected.png
// and DIR/<name>-diff.png), 2 on bad usage.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>
#include <glm/glm.hpp>

#include "curvetext/error.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/image.hpp"
#include "common/hud.hpp"
#include "common/world.hpp"
#include "support/coverage.hpp"
#include "support/union_coverage.hpp"

namespace {

using curvetext::Image;
using curvetext::Outline;
using curvetext::test::Coverage;
using example::TextItem;

constexpr int kSceneLevels = 1;          // per channel, 0-255, outside the text
constexpr int kInkMarginPx = 1;          // the exact coverage's support grown by this much
constexpr int kMinContrast = 48;         // levels between text and background for a pixel to be judged
constexpr double kEdgeMeanLimit = 0.01;  // mean |coverage error| over the edge band
constexpr double kMaxLimit = 0.08;       // largest |coverage error| of any pixel
constexpr double kInkLimit = 0.01;       // |total ink / exact total ink - 1|
constexpr double kPlaneLimitPx = 1e-3;   // plane transform against glm's projection
constexpr std::size_t kMinEdgePixels = 30;

struct Args {
  std::string scene, text, no_text, out, expect_gl;
};

Args parse(int argc, char** argv) {
  Args a;
  std::map<std::string, std::string*> named{{"--scene", &a.scene},
                                            {"--text", &a.text},
                                            {"--no-text", &a.no_text},
                                            {"--out", &a.out},
                                            {"--expect-gl", &a.expect_gl}};
  for (int i = 1; i + 1 < argc; i += 2) {
    const auto it = named.find(argv[i]);
    if (it == named.end()) throw std::invalid_argument(std::string("unknown option ") + argv[i]);
    *it->second = argv[i + 1];
  }
  if (argc % 2 == 0 || (a.scene != "world" && a.scene != "hud") || a.text.empty() || a.no_text.empty() || a.out.empty())
    throw std::invalid_argument(
        "usage: check_example_screenshot --scene world|hud --text SHOT.png --no-text SHOT.png --out DIR "
        "[--expect-gl TEXT]");
  return a;
}

// "key value" lines written by the app next to its screenshot.
std::map<std::string, std::string> read_info(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::map<std::string, std::string> info;
  for (std::string line; std::getline(in, line);) {
    const auto space = line.find(' ');
    if (space != std::string::npos) info[line.substr(0, space)] = line.substr(space + 1);
  }
  for (const char* key : {"frame", "score", "fps", "gl"})
    if (!info.count(key)) throw std::runtime_error(path + " has no '" + key + "' line");
  return info;
}

struct NamedItem {
  std::string name;
  TextItem item;
};

// The frame's text as the app drew it, in drawing order.
std::vector<NamedItem> frame_items(const Args& args, const std::map<std::string, std::string>& info,
                                   curvetext::FontCollection& fonts, int width, int height) {
  std::vector<NamedItem> items;
  if (args.scene == "world") {
    const example::WorldLabel label = example::world_label(fonts.resolve(example::kFontPath));
    const glm::mat4 camera = example::camera_at(std::stoi(info.at("frame")), width, height);
    TextItem item = label.text;
    item.placement = example::label_placement(label, camera, width, height);
    items.push_back({"label", item});
  }
  const example::Hud hud(fonts, width, height);
  items.push_back({"score", hud.score_item(info.at("score"))});
  items.push_back({"fps", hud.fps_item(info.at("fps"))});
  int n = 0;
  for (TextItem& item : hud.paragraph_items()) items.push_back({"paragraph" + std::to_string(n++), item});
  return items;
}

// The world camera's plane transform maps points as glm's projection does.
bool check_plane_transform(const std::map<std::string, std::string>& info, int width, int height) {
  const glm::mat4 vp = example::camera_at(std::stoi(info.at("frame")), width, height);
  const curvetext::Transform t = curvetext::Transform::plane_to_viewport(glm::value_ptr(vp), width, height);
  double worst = 0.0;
  for (const glm::vec2 p : {glm::vec2(-3, -1), glm::vec2(3, -1), glm::vec2(3, 1), glm::vec2(-2, 1.5f)}) {
    const glm::vec4 clip = vp * glm::vec4(p, 0.0f, 1.0f);
    const double x = (clip.x / clip.w + 1.0) / 2.0 * width, y = (1.0 - clip.y / clip.w) / 2.0 * height;
    const curvetext::Vec2 q = t.apply({p.x, -p.y});
    worst = std::max({worst, std::abs(q.x - x), std::abs(q.y - y)});
  }
  std::printf("plane transform: largest distance from glm's projection %.2g px (limit %.0g)\n", worst, kPlaneLimitPx);
  return worst <= kPlaneLimitPx;
}

// The item's glyph outlines in window pixels.
Outline pixel_outline(const TextItem& item) {
  Outline all;
  for (const curvetext::PlacedGlyph& g : item.glyphs) {
    const Outline glyph = item.font->glyph_outline(g.glyph_id);
    for (curvetext::Contour c : glyph.contours()) {
      for (curvetext::Segment& s : c.segments)
        for (curvetext::Vec2& p : s.p) p = p + curvetext::Vec2{g.x, g.y};
      all.contours().push_back(std::move(c));
    }
  }
  Outline placed = curvetext::test::place_outline(all, item.placement);
  if (!item.placement.transform.is_identity())
    placed = curvetext::test::transform_outline(placed, item.placement.transform);
  return placed;
}

// Pixels where `c` is above zero, grown by `margin` pixels (a square).
std::vector<bool> support(const Coverage& c, int margin) {
  std::vector<bool> inked(c.value.size(), false);
  for (int y = 0; y < c.height; ++y)
    for (int x = 0; x < c.width; ++x) {
      if (c.at(x, y) <= 0.0f) continue;
      for (int j = std::max(0, y - margin); j <= std::min(c.height - 1, y + margin); ++j)
        for (int i = std::max(0, x - margin); i <= std::min(c.width - 1, x + margin); ++i)
          inked[static_cast<std::size_t>(j) * c.width + i] = true;
    }
  return inked;
}

int level(float channel) { return static_cast<int>(std::lround(std::clamp(channel, 0.0f, 1.0f) * 255.0f)); }

// The coverage the screenshot shows over `background` in the item's colour,
// and the exact one, on the item's pixels with enough contrast to tell.
struct Observed {
  Coverage seen, exact;
  std::size_t judged = 0, skipped = 0;
};

Observed observe(const Image& shot, const Image& background, const Coverage& exact, const std::vector<bool>& zone,
                 const curvetext::Color& color) {
  Observed o{Coverage(exact.width, exact.height), Coverage(exact.width, exact.height)};
  const int ink[3] = {level(color.r), level(color.g), level(color.b)};
  for (int y = 0; y < exact.height; ++y)
    for (int x = 0; x < exact.width; ++x) {
      if (!zone[static_cast<std::size_t>(y) * exact.width + x]) continue;
      const std::uint8_t* bg = background.pixel(x, y);
      int channel = 0;  // the channel where text and background differ most
      for (int k = 1; k < 3; ++k)
        if (std::abs(ink[k] - bg[k]) > std::abs(ink[channel] - bg[channel])) channel = k;
      const int contrast = ink[channel] - bg[channel];
      if (std::abs(contrast) < kMinContrast) {
        ++o.skipped;
        continue;
      }
      o.seen.at(x, y) = static_cast<float>(shot.pixel(x, y)[channel] - bg[channel]) / static_cast<float>(contrast);
      o.exact.at(x, y) = exact.at(x, y);
      ++o.judged;
    }
  return o;
}

// background * (1 - c) + colour * c, as the renderer blends (source-over on
// the stored values).
void blend(Image& image, const Coverage& c, const curvetext::Color& color) {
  const float ink[3] = {color.r * 255.0f, color.g * 255.0f, color.b * 255.0f};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float a = c.at(x, y) * color.a;
      if (a <= 0.0f) continue;
      std::uint8_t* p = image.pixel(x, y);
      for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>(std::lround(p[k] * (1.0f - a) + ink[k] * a));
    }
}

// |a - b| per channel, times 8, on black.
Image difference(const Image& a, const Image& b) {
  Image d(a.width, a.height);
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    for (int k = 0; k < 3; ++k)
      d.rgba[i + k] = static_cast<std::uint8_t>(std::min(255, 8 * std::abs(a.rgba[i + k] - b.rgba[i + k])));
    d.rgba[i + 3] = 255;
  }
  return d;
}

struct SceneResult {
  std::size_t compared = 0, differing = 0;
  int largest = 0, first_x = -1, first_y = -1;
};

SceneResult compare_scene(const Image& shot, const Image& background, const std::vector<bool>& text_zone) {
  SceneResult r;
  for (int y = 0; y < shot.height; ++y)
    for (int x = 0; x < shot.width; ++x) {
      if (text_zone[static_cast<std::size_t>(y) * shot.width + x]) continue;
      ++r.compared;
      int d = 0;
      for (int k = 0; k < 3; ++k) d = std::max(d, std::abs(shot.pixel(x, y)[k] - background.pixel(x, y)[k]));
      r.largest = std::max(r.largest, d);
      if (d > kSceneLevels && r.differing++ == 0) {
        r.first_x = x;
        r.first_y = y;
      }
    }
  return r;
}

int check(const Args& args) {
  const Image shot = curvetext::read_png(args.text);
  const Image background = curvetext::read_png(args.no_text);
  if (shot.width != background.width || shot.height != background.height)
    throw std::runtime_error("the screenshots differ in size");
  const auto info = read_info(args.text + ".txt");
  std::printf("%s: %dx%d, frame %s, GL_VERSION %s\n", args.text.c_str(), shot.width, shot.height,
              info.at("frame").c_str(), info.at("gl").c_str());
  bool ok = true;
  if (!args.expect_gl.empty() && info.at("gl").find(args.expect_gl) == std::string::npos) {
    std::printf("FAIL: the context is not '%s'\n", args.expect_gl.c_str());
    ok = false;
  }
  if (args.scene == "world") ok = check_plane_transform(info, shot.width, shot.height) && ok;

  curvetext::FontCollection fonts;
  const std::vector<NamedItem> items = frame_items(args, info, fonts, shot.width, shot.height);
  std::vector<bool> text_zone(shot.rgba.size() / 4, false);
  Image expected = background;
  for (const NamedItem& named : items) {
    const Coverage exact = curvetext::test::union_coverage(pixel_outline(named.item), shot.width, shot.height);
    const std::vector<bool> zone = support(exact, kInkMarginPx);
    for (std::size_t i = 0; i < zone.size(); ++i) text_zone[i] = text_zone[i] || zone[i];
    blend(expected, exact, named.item.color);

    const Observed o = observe(shot, background, exact, zone, named.item.color);
    const curvetext::test::CoverageStats s = curvetext::test::compare(o.seen, o.exact);
    const bool item_ok = s.edge_pixels >= kMinEdgePixels && s.edge_mean_abs <= kEdgeMeanLimit &&
                         s.max_abs <= kMaxLimit && std::abs(s.ink_ratio - 1.0) <= kInkLimit;
    std::printf(
        "%-12s %s: %zu px judged (%zu low-contrast skipped), edge band %zu px, mean |error| %.4f "
        "(limit %.2f), max %.3f (limit %.2f), ink ratio %.4f (limit 1 +- %.2f)\n",
        named.name.c_str(), item_ok ? "ok  " : "FAIL", o.judged, o.skipped, s.edge_pixels, s.edge_mean_abs,
        kEdgeMeanLimit, s.max_abs, kMaxLimit, s.ink_ratio, kInkLimit);
    ok = ok && item_ok;
  }

  const SceneResult scene = compare_scene(shot, background, text_zone);
  const bool scene_ok = scene.differing == 0;
  std::printf("scene        %s: %zu px outside the text, %zu differ by more than %d (largest %d",
              scene_ok ? "ok  " : "FAIL", scene.compared, scene.differing, kSceneLevels, scene.largest);
  if (!scene_ok) std::printf(", first at %d,%d", scene.first_x, scene.first_y);
  std::printf(")\n");
  ok = ok && scene_ok;

  if (!ok) {
    const std::string stem = args.out + "/" + args.scene;
    curvetext::write_png(expected, stem + "-expected.png");
    curvetext::write_png(difference(shot, expected), stem + "-diff.png");
    std::printf("wrote %s-expected.png and %s-diff.png (|screenshot - expected| x 8)\n", stem.c_str(), stem.c_str());
  }
  std::printf("%s\n", ok ? "PASS" : "FAIL");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  try {
    args = parse(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  try {
    return check(args);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "check_example_screenshot: %s\n", e.what());
    return 1;
  }
}
