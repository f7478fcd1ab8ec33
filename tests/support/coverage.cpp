#include "support/coverage.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "curvetext/error.hpp"

namespace curvetext::test {

Coverage coverage_from_black_on_white(const Image& image) {
  Coverage c(image.width, image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) c.at(x, y) = 1.0f - static_cast<float>(image.pixel(x, y)[0]) / 255.0f;
  return c;
}

namespace {

struct FtLibrary {
  FT_Library lib = nullptr;
  FtLibrary() {
    if (FT_Init_FreeType(&lib)) throw std::runtime_error("FT_Init_FreeType failed");
  }
  ~FtLibrary() { FT_Done_FreeType(lib); }
};

// Builds an FT_Outline in FreeType's y-up raster space of a bitmap `height`
// rows tall, from an outline already in pixel space (y down), scaled by k.
struct FtOutlineData {
  std::vector<FT_Vector> points;
  std::vector<char> tags;
  std::vector<short> contours;
};

FT_Pos to26_6(double v) { return static_cast<FT_Pos>(std::lround(v * 64.0)); }

FtOutlineData to_freetype(const Outline& pixel_outline, double k, int bitmap_height) {
  FtOutlineData d;
  auto add = [&](Vec2 p, char tag) {
    d.points.push_back({to26_6(p.x * k), to26_6(bitmap_height - p.y * k)});
    d.tags.push_back(tag);
  };
  for (const Contour& c : pixel_outline.contours()) {
    if (c.segments.empty()) continue;
    add(c.segments.front().start(), FT_CURVE_TAG_ON);
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
      const Segment& s = c.segments[i];
      const bool last = i + 1 == c.segments.size();
      switch (s.kind) {
        case Segment::Kind::Line:
          if (!last) add(s.p[1], FT_CURVE_TAG_ON);
          break;
        case Segment::Kind::Conic:
          if (s.weight != 1.0) throw std::runtime_error("FreeType reference needs weight-1 conics");
          add(s.p[1], FT_CURVE_TAG_CONIC);
          if (!last) add(s.p[2], FT_CURVE_TAG_ON);
          break;
        case Segment::Kind::Cubic:
          add(s.p[1], FT_CURVE_TAG_CUBIC);
          add(s.p[2], FT_CURVE_TAG_CUBIC);
          if (!last) add(s.p[3], FT_CURVE_TAG_ON);
          break;
      }
    }
    d.contours.push_back(static_cast<short>(d.points.size() - 1));
  }
  return d;
}

}  // namespace

Outline line_outline(const Font& font, const ShapedLine& line) {
  Outline all;
  Vec2 pen{0, 0};
  for (const ShapedGlyph& g : line.glyphs) {
    const Vec2 origin = pen + Vec2{g.x_offset, g.y_offset};
    const Outline glyph = font.glyph_outline(g.glyph_id);
    for (Contour c : glyph.contours()) {
      for (Segment& s : c.segments)
        for (Vec2& p : s.p) p = p + origin;
      all.contours().push_back(std::move(c));
    }
    pen = pen + Vec2{g.x_advance, g.y_advance};
  }
  return all;
}

Outline place_outline(const Outline& outline, const Placement& pl) {
  Outline out = outline;
  auto map = [&](Vec2 p) { return Vec2{pl.scale * p.x + pl.origin_x, pl.origin_y - pl.scale * p.y}; };
  for (Contour& c : out.contours())
    for (Segment& s : c.segments)
      for (Vec2& p : s.p) p = map(p);
  return out;
}

Outline transform_outline(const Outline& in, const Transform& t) {
  Outline out = in;
  for (Contour& c : out.contours())
    for (Segment& s : c.segments) {
      if (s.kind == Segment::Kind::Conic) {
        const double w0 = t.w(s.p[0]), w1 = t.w(s.p[1]), w2 = t.w(s.p[2]);
        s.weight = s.weight * w1 / std::sqrt(w0 * w2);
      } else if (s.kind == Segment::Kind::Cubic && !t.is_affine()) {
        throw Error(ErrorCode::InvalidArgument, "cubics under perspective are rational cubics");
      }
      const int n = s.kind == Segment::Kind::Line ? 2 : s.kind == Segment::Kind::Conic ? 3 : 4;
      for (int i = 0; i < n; ++i) s.p[i] = t.apply(s.p[i]);
    }
  return out;
}

Coverage freetype_reference(const Outline& outline, const Placement& placement, int width, int height,
                            int supersample) {
  static FtLibrary ft;
  const Outline px = place_outline(outline, placement);
  const int k = std::max(1, supersample);
  const int bw = width * k, bh = height * k;
  FtOutlineData data = to_freetype(px, k, bh);
  Coverage result(width, height);
  if (data.points.empty()) return result;
  if (data.points.size() > 32767) throw std::runtime_error("outline too large for FT_Outline");

  FT_Outline ftol{};
  ftol.n_points = static_cast<short>(data.points.size());
  ftol.n_contours = static_cast<short>(data.contours.size());
  ftol.points = data.points.data();
  ftol.tags = data.tags.data();
  ftol.contours = data.contours.data();
  ftol.flags = FT_OUTLINE_NONE;  // nonzero winding

  std::vector<unsigned char> buffer(static_cast<std::size_t>(bw) * bh, 0);
  FT_Bitmap bitmap{};
  bitmap.rows = static_cast<unsigned>(bh);
  bitmap.width = static_cast<unsigned>(bw);
  bitmap.pitch = bw;
  bitmap.buffer = buffer.data();
  bitmap.num_grays = 256;
  bitmap.pixel_mode = FT_PIXEL_MODE_GRAY;
  FT_Raster_Params params{};
  params.target = &bitmap;
  params.source = &ftol;
  params.flags = FT_RASTER_FLAG_AA;
  if (FT_Outline_Render(ft.lib, &ftol, &params)) throw std::runtime_error("FT_Outline_Render failed");

  // FreeType's bitmap row 0 is the top of the y-up raster space = our row 0.
  const float norm = 1.0f / (255.0f * static_cast<float>(k * k));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      unsigned sum = 0;
      for (int sy = 0; sy < k; ++sy)
        for (int sx = 0; sx < k; ++sx) sum += buffer[static_cast<std::size_t>(y * k + sy) * bw + (x * k + sx)];
      result.at(x, y) = static_cast<float>(sum) * norm;
    }
  return result;
}

Coverage sampled_reference(const std::function<bool(double, double)>& inside, int width, int height, int n) {
  Coverage c(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      int count = 0;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          if (inside(x + (i + 0.5) / n, y + (j + 0.5) / n)) ++count;
      c.at(x, y) = static_cast<float>(count) / static_cast<float>(n * n);
    }
  return c;
}

CoverageStats compare(const Coverage& result, const Coverage& reference) {
  if (result.width != reference.width || result.height != reference.height)
    throw std::runtime_error("coverage images differ in size");
  const int w = result.width, h = result.height;
  std::vector<unsigned char> edge(static_cast<std::size_t>(w) * h, 0);
  auto partial = [](float c) { return c > 0.02f && c < 0.98f; };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (partial(result.at(x, y)) || partial(reference.at(x, y)))
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx >= 0 && yy >= 0 && xx < w && yy < h) edge[static_cast<std::size_t>(yy) * w + xx] = 1;
          }
  CoverageStats s;
  double sum_abs = 0, sum_edge = 0, ink = 0, ink_ref = 0;
  for (std::size_t i = 0; i < result.value.size(); ++i) {
    const double d = std::abs(static_cast<double>(result.value[i]) - reference.value[i]);
    sum_abs += d;
    s.max_abs = std::max(s.max_abs, d);
    if (edge[i]) {
      sum_edge += d;
      ++s.edge_pixels;
    }
    ink += result.value[i];
    ink_ref += reference.value[i];
  }
  s.mean_abs = result.value.empty() ? 0 : sum_abs / static_cast<double>(result.value.size());
  s.edge_mean_abs = s.edge_pixels ? sum_edge / static_cast<double>(s.edge_pixels) : 0;
  s.ink_ratio = ink_ref > 0 ? ink / ink_ref : (ink > 0 ? 1e9 : 1.0);
  return s;
}

void expect_coverage(const std::string& name, const Coverage& result, const Coverage& reference,
                     const CoverageStats& stats, double edge_limit, double ink_limit) {
  std::printf("%-40s edge %.4f  max %.3f  ink %.4f  (%dx%d)\n", name.c_str(), stats.edge_mean_abs, stats.max_abs,
              stats.ink_ratio, result.width, result.height);
  const bool ok = stats.edge_mean_abs <= edge_limit && std::abs(stats.ink_ratio - 1.0) <= ink_limit;
  if (!ok) write_comparison(name, result, reference);
  EXPECT_GT(stats.edge_pixels, 100u) << name << ": nothing was drawn";
  EXPECT_LE(stats.edge_mean_abs, edge_limit) << name;
  EXPECT_NEAR(stats.ink_ratio, 1.0, ink_limit) << name;
}

std::string write_comparison(const std::string& name, const Coverage& result, const Coverage& reference) {
  const std::string dir = CURVETEXT_TEST_OUTPUT_DIR;
  std::filesystem::create_directories(dir);
  auto gray = [](const Coverage& c) {
    Image img(c.width, c.height);
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x) {
        const auto v = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - std::clamp(c.at(x, y), 0.0f, 1.0f))));
        std::uint8_t* p = img.pixel(x, y);
        p[0] = p[1] = p[2] = v;
        p[3] = 255;
      }
    return img;
  };
  Image diff(result.width, result.height);
  for (int y = 0; y < result.height; ++y)
    for (int x = 0; x < result.width; ++x) {
      const float d = result.at(x, y) - reference.at(x, y);
      const auto m = static_cast<std::uint8_t>(std::lround(255.0 * std::min(1.0f, std::abs(d) * 4.0f)));
      std::uint8_t* p = diff.pixel(x, y);
      p[0] = d > 0 ? 255 : static_cast<std::uint8_t>(255 - m);
      p[1] = static_cast<std::uint8_t>(255 - m);
      p[2] = d < 0 ? 255 : static_cast<std::uint8_t>(255 - m);
      p[3] = 255;
    }
  write_png(gray(result), dir + "/" + name + "-result.png");
  write_png(gray(reference), dir + "/" + name + "-reference.png");
  write_png(diff, dir + "/" + name + "-diff.png");
  return dir;
}

}  // namespace curvetext::test
