// Colour glyphs (color_glyph.hpp): COLR v0 layers and CBDT/sbix bitmaps read
// by FreeType, and COLR v1 paint graphs (solid fills, gradients and their
// transforms inside a glyph) read here.

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_COLOR_H
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/paint.hpp"
#include "curvetext/transform.hpp"
#include "curvetext/tolerances.hpp"
#include "font/font_impl.hpp"

namespace curvetext {

namespace {

using Impl = FontAccess::Impl;

std::string glyph_text(std::uint32_t glyph_id, const Impl& im) {
  return "glyph " + std::to_string(glyph_id) + " of " + im.path;
}

void check_glyph_id(std::uint32_t glyph_id, const Impl& im) {
  if (glyph_id >= static_cast<std::uint32_t>(im.ft_face->num_glyphs))
    throw Error(ErrorCode::FontInvalid, "glyph id " + std::to_string(glyph_id) + " out of range (font has " +
                                            std::to_string(im.ft_face->num_glyphs) + " glyphs): " + im.path);
}

// COLR v1 paint formats (OpenType 1.9, COLR table) by name, for refusals.
std::string paint_name(unsigned format) {
  if (format == 3) return "a variable solid fill (PaintVarSolid)";
  if (format == 5) return "a variable linear gradient (PaintVarLinearGradient)";
  if (format == 7) return "a variable radial gradient (PaintVarRadialGradient)";
  if (format == 9) return "a variable sweep gradient (PaintVarSweepGradient)";
  if (format >= 12 && format <= 31 && format % 2 == 1)
    return "a variable transform (PaintVarTransform, Translate, Scale, Rotate or Skew)";
  if (format == 32) return "a composite (PaintComposite)";
  if (format == 1) return "a layer list (PaintColrLayers)";
  if (format == 10) return "a glyph (PaintGlyph)";
  if (format == 11) return "a colour glyph (PaintColrGlyph)";
  return "paint format " + std::to_string(format) + ", which OpenType does not define";
}

// A 2 x 3 affine map of font units (COLR's Affine2x3): x' = xx x + xy y + dx,
// y' = yx x + yy y + dy.
struct Affine {
  double xx = 1, yx = 0, xy = 0, yy = 1, dx = 0, dy = 0;
  Affine operator*(const Affine& o) const {  // this after o
    return {xx * o.xx + xy * o.yx, yx * o.xx + yy * o.yx,      xx * o.xy + xy * o.yy,
            yx * o.xy + yy * o.yy, xx * o.dx + xy * o.dy + dx, yx * o.dx + yy * o.dy + dy};
  }
  static Affine around(const Affine& m, double cx, double cy) {
    return Affine{1, 0, 0, 1, cx, cy} * m * Affine{1, 0, 0, 1, -cx, -cy};
  }
  Vec2 apply(Vec2 p) const { return {xx * p.x + xy * p.y + dx, yx * p.x + yy * p.y + dy}; }
};

constexpr double kPi = 3.14159265358979323846;

// Reads the COLR table's v1 paint graphs itself: Debian 12's FreeType is
// built with its COLR v1 API disabled (it returns no paint for any glyph),
// and HarfBuzz 6 has none. Every read is bounds-checked against the table.
// Supported: layer lists, glyphs filled with a solid colour or a linear,
// radial or sweep gradient under static transforms, references to other
// colour glyphs; anything else is refused by name.
struct PaintWalker {
  const Impl& im;
  std::uint32_t root_glyph;
  const FT_Color* palette;
  FT_UShort palette_size;
  std::vector<ColorLayer>& out;
  const std::uint8_t* table = nullptr;
  std::size_t size = 0;

  [[noreturn]] void refuse(const std::string& what) const {
    throw Error(ErrorCode::FontInvalid, "COLR v1 " + glyph_text(root_glyph, im) + ": " + what);
  }
  std::uint32_t read(std::size_t at, int bytes) const {
    if (at > size || static_cast<std::size_t>(bytes) > size - at) refuse("the COLR table is cut short");
    std::uint32_t v = 0;
    for (int i = 0; i < bytes; ++i) v = v << 8 | table[at + static_cast<std::size_t>(i)];
    return v;
  }

  ColorLayer solid(std::uint32_t glyph_id, std::uint32_t palette_index, double alpha) const {
    ColorLayer layer;
    layer.glyph_id = glyph_id;
    alpha = std::clamp(alpha, 0.0, 1.0);
    if (palette_index == 0xFFFF) {
      layer.foreground = true;
      layer.color = Color{0, 0, 0, static_cast<float>(alpha)};
      return layer;
    }
    if (palette == nullptr || palette_index >= palette_size)
      refuse("palette entry " + std::to_string(palette_index) + " is past the palette's " +
             std::to_string(palette_size));
    const FT_Color& c = palette[palette_index];
    layer.color = Color{c.red / 255.0f, c.green / 255.0f, c.blue / 255.0f, static_cast<float>(c.alpha / 255.0 * alpha)};
    return layer;
  }

  void add(const ColorLayer& layer) {
    if (out.size() >= tolerance::kMaxColorLayers)
      refuse("more than " + std::to_string(tolerance::kMaxColorLayers) + " layers");
    check_glyph_id(layer.glyph_id, im);
    out.push_back(layer);
  }

  // The offset of a glyph's paint in the BaseGlyphList (binary search), or 0.
  std::size_t glyph_paint(std::uint32_t glyph_id) const {
    const std::size_t list = read(14, 4);
    if (list == 0) return 0;
    std::size_t lo = 0, hi = read(list, 4);
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      const std::uint32_t gid = read(list + 4 + mid * 6, 2);
      if (gid == glyph_id) return list + read(list + 4 + mid * 6 + 2, 4);
      if (gid < glyph_id)
        lo = mid + 1;
      else
        hi = mid;
    }
    return 0;
  }

  double f2dot14(std::size_t at) const { return static_cast<std::int16_t>(read(at, 2)) / 16384.0; }
  double fword(std::size_t at) const { return static_cast<std::int16_t>(read(at, 2)); }
  double fixed(std::size_t at) const { return static_cast<std::int32_t>(read(at, 4)) / 65536.0; }

  // A static transform paint's map (its child's space -> its own), and its child.
  Affine transform_of(std::size_t paint, unsigned format, std::size_t& child) const {
    child = paint + read(paint + 1, 3);
    const std::size_t p = paint + 4;
    if (format == 12) {  // PaintTransform: Offset24 to an Affine2x3 of Fixed
      const std::size_t t = paint + read(p, 3);
      return {fixed(t), fixed(t + 4), fixed(t + 8), fixed(t + 12), fixed(t + 16), fixed(t + 20)};
    }
    if (format == 14) return {1, 0, 0, 1, fword(p), fword(p + 2)};
    if (format == 16 || format == 18) {
      const Affine k{f2dot14(p), 0, 0, f2dot14(p + 2), 0, 0};
      return format == 16 ? k : Affine::around(k, fword(p + 4), fword(p + 6));
    }
    if (format == 20 || format == 22) {
      const Affine k{f2dot14(p), 0, 0, f2dot14(p), 0, 0};
      return format == 20 ? k : Affine::around(k, fword(p + 2), fword(p + 4));
    }
    if (format == 24 || format == 26) {  // counter-clockwise, 180 degrees per 1.0
      const double a = f2dot14(p) * kPi;
      const Affine r{std::cos(a), std::sin(a), -std::sin(a), std::cos(a), 0, 0};
      return format == 24 ? r : Affine::around(r, fword(p + 2), fword(p + 4));
    }
    // PaintSkew(AroundCenter): a positive x angle turns the y axis counter-clockwise.
    const Affine k{1, std::tan(f2dot14(p + 2) * kPi), std::tan(-f2dot14(p) * kPi), 1, 0, 0};
    return format == 28 ? k : Affine::around(k, fword(p + 4), fword(p + 6));
  }

  // The layer a PaintGlyph's fill paint gives: a solid colour, or a gradient
  // under the transforms `m` met on the way (paint space -> glyph space).
  ColorLayer fill(std::size_t paint, const Affine& m, int depth) {
    if (++visited > tolerance::kMaxColorPaints)
      refuse("more than " + std::to_string(tolerance::kMaxColorPaints) + " paints");
    if (depth > tolerance::kMaxColorPaintDepth)
      refuse("paints nested deeper than " + std::to_string(tolerance::kMaxColorPaintDepth) + " (a cycle?)");
    const unsigned format = read(paint, 1);
    if (format == 2) return solid(0, read(paint + 1, 2), f2dot14(paint + 3));
    if (format == 4 || format == 6 || format == 8) return gradient(paint, format, m);
    if (format >= 12 && format <= 30 && format % 2 == 0) {
      std::size_t child = 0;
      const Affine t = transform_of(paint, format, child);
      return fill(child, m * t, depth + 1);
    }
    refuse(paint_name(format) + " inside a glyph is not supported yet");
  }

  // A ColorLine's stops sorted by offset (stably) into g, with their offsets
  // mapped from [first, last] to [0, 1]; returns first and last.
  std::pair<double, double> color_line(std::size_t line, Gradient& g, ColorLayer& layer) const {
    const unsigned extend = read(line, 1);
    g.spread = extend == 1 ? Gradient::Spread::Repeat : extend == 2 ? Gradient::Spread::Reflect : Gradient::Spread::Pad;
    const std::size_t count = read(line + 1, 2);
    if (count == 0) refuse("a gradient's colour line has no stops");
    if (count > static_cast<std::size_t>(kMaxGradientStops))
      refuse("a gradient's colour line has " + std::to_string(count) + " stops; at most " +
             std::to_string(kMaxGradientStops) + " are drawn");
    struct Stop {
      double offset;
      Color color;
      bool foreground;
    };
    std::vector<Stop> stops;
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t at = line + 3 + 6 * k;
      const ColorLayer c = solid(0, read(at + 2, 2), f2dot14(at + 4));
      stops.push_back(Stop{f2dot14(at), c.color, c.foreground});
    }
    std::stable_sort(stops.begin(), stops.end(), [](const Stop& a, const Stop& b) { return a.offset < b.offset; });
    const double first = stops.front().offset, last = stops.back().offset;
    const double span = last > first ? last - first : 1.0;  // one offset: a hard step there
    float previous = 0.0f;
    for (std::size_t k = 0; k < stops.size(); ++k) {
      const float offset = std::clamp(static_cast<float>((stops[k].offset - first) / span), previous, 1.0f);
      g.stops.push_back(GradientStop{offset, stops[k].color});
      if (stops[k].foreground) layer.foreground_stops |= 1u << k;
      previous = offset;
    }
    return {first, first + span};
  }

  ColorLayer gradient(std::size_t paint, unsigned format, const Affine& m) const {
    ColorLayer layer;
    Gradient& g = layer.gradient.emplace();
    const auto [s0, s1] = color_line(paint + read(paint + 1, 3), g, layer);
    const std::size_t p = paint + 4;
    auto at = [](Vec2 a, Vec2 b, double t) { return a + (b - a) * t; };
    if (format == 4) {  // PaintLinearGradient: p0, p1, p2
      const Vec2 p0{fword(p), fword(p + 2)}, p1{fword(p + 4), fword(p + 6)}, p2{fword(p + 8), fword(p + 10)};
      // Colour is constant along lines parallel to p0 -> p2: p1 projected
      // onto that line's normal through p0 gives the two-point form.
      const Vec2 d = p2 - p0, n{-d.y, d.x};
      if (!(dot(n, n) > 0.0)) refuse("a linear gradient's p0 and p2 are one point");
      const Vec2 q = p0 + n * (dot(p1 - p0, n) / dot(n, n));
      if (q == p0) refuse("a linear gradient's p1 lies on the line through p0 and p2");
      g.kind = Gradient::Kind::Linear;
      g.start = at(p0, q, s0);
      g.end = at(p0, q, s1);
    } else if (format == 6) {  // PaintRadialGradient: c0, r0, c1, r1
      const Vec2 c0{fword(p), fword(p + 2)}, c1{fword(p + 6), fword(p + 8)};
      const double r0 = read(p + 4, 2), r1 = read(p + 10, 2);
      g.kind = Gradient::Kind::Radial;
      g.focus = at(c0, c1, s0);
      g.centre = at(c0, c1, s1);
      g.focal_radius = r0 + (r1 - r0) * s0;
      g.radius = r0 + (r1 - r0) * s1;
    } else {  // PaintSweepGradient: centre, start and end angles (180 degrees per 1.0)
      const double a0 = f2dot14(p + 4) * 180.0, a1 = f2dot14(p + 6) * 180.0;
      g.kind = Gradient::Kind::Sweep;
      g.centre = {fword(p), fword(p + 2)};
      g.start_angle = a0 + (a1 - a0) * s0;
      g.end_angle = a0 + (a1 - a0) * s1;
    }
    const double det = m.xx * m.yy - m.xy * m.yx;
    if (!std::isfinite(det) || det == 0.0) refuse("a gradient's transform is singular");
    const double ixx = m.yy / det, ixy = -m.xy / det, iyx = -m.yx / det, iyy = m.xx / det;
    g.from_outline =
        Transform{{ixx, ixy, -(ixx * m.dx + ixy * m.dy), iyx, iyy, -(iyx * m.dx + iyy * m.dy), 0.0, 0.0, 1.0}};
    try {
      validate_gradient(g);
    } catch (const Error& e) {
      refuse(e.what());
    }
    return layer;
  }

  std::size_t visited = 0;

  void walk(std::size_t paint, int depth) {
    // Layer lists may share paints: a graph a few levels deep can name
    // exponentially many, so the paints visited are counted too.
    if (++visited > tolerance::kMaxColorPaints)
      refuse("more than " + std::to_string(tolerance::kMaxColorPaints) + " paints");
    if (depth > tolerance::kMaxColorPaintDepth)
      refuse("paints nested deeper than " + std::to_string(tolerance::kMaxColorPaintDepth) + " (a cycle?)");
    const unsigned format = read(paint, 1);
    if (format == 1) {  // PaintColrLayers: numLayers u8, firstLayerIndex u32 into the LayerList
      const std::size_t count = read(paint + 1, 1), first = read(paint + 2, 4), list = read(18, 4);
      if (list == 0 || first + count > read(list, 4)) refuse("PaintColrLayers reaches past the LayerList");
      for (std::size_t k = first; k < first + count; ++k) walk(list + read(list + 4 + 4 * k, 4), depth + 1);
    } else if (format == 10) {  // PaintGlyph: paint Offset24 (from here), glyphID u16
      ColorLayer layer = fill(paint + read(paint + 1, 3), Affine{}, depth + 1);
      layer.glyph_id = read(paint + 4, 2);
      add(layer);
    } else if (format == 11) {  // PaintColrGlyph: glyphID u16
      const std::uint32_t glyph = read(paint + 1, 2);
      const std::size_t inner = glyph_paint(glyph);
      if (inner == 0) refuse("PaintColrGlyph names glyph " + std::to_string(glyph) + ", which has no paint");
      walk(inner, depth + 1);
    } else if (format == 2 || (format >= 4 && format <= 8 && format % 2 == 0)) {
      refuse("a fill outside a glyph (filling the whole clip box) is not supported yet");
    } else if (format >= 12 && format <= 30 && format % 2 == 0) {
      refuse(
          "a transform around a glyph (PaintTransform, Translate, Scale, Rotate or Skew above PaintGlyph) is not "
          "supported yet (under PaintGlyph it is)");
    } else {
      refuse(paint_name(format) + " is not supported yet");
    }
  }
};

}  // namespace

ColorFormat Font::color_format() const { return impl_->color_format; }

std::vector<ColorLayer> Font::color_layers(std::uint32_t glyph_id) const {
  const Impl& im = *impl_;
  check_glyph_id(glyph_id, im);
  std::vector<ColorLayer> layers;
  if (im.color_format != ColorFormat::Layers) return layers;
  std::lock_guard<std::mutex> lock(im.ft_mutex);
  FT_Color* palette = nullptr;
  FT_Palette_Data data{};
  if (FT_Palette_Data_Get(im.ft_face, &data) != 0 || FT_Palette_Select(im.ft_face, 0, &palette) != 0)
    palette = nullptr;  // a font with no CPAL can still use the text's colour (0xFFFF)
  const FT_UShort palette_size = palette ? data.num_palette_entries : 0;
  PaintWalker walker{im, glyph_id, palette, palette_size, layers};

  FT_LayerIterator it{};
  it.p = nullptr;
  FT_UInt layer_glyph = 0, color_index = 0;
  while (FT_Get_Color_Glyph_Layer(im.ft_face, glyph_id, &layer_glyph, &color_index, &it)) {
    if (layers.size() >= tolerance::kMaxColorLayers)
      throw Error(ErrorCode::FontInvalid, "COLR " + glyph_text(glyph_id, im) + " has more than " +
                                              std::to_string(tolerance::kMaxColorLayers) + " layers");
    check_glyph_id(layer_glyph, im);
    layers.push_back(walker.solid(layer_glyph, color_index, 1.0));
  }
  if (!layers.empty()) return layers;  // COLR v0

  const detail::HbBlobPtr blob(hb_face_reference_table(hb_font_get_face(im.hb_font), HB_TAG('C', 'O', 'L', 'R')));
  unsigned int length = 0;
  walker.table = reinterpret_cast<const std::uint8_t*>(hb_blob_get_data(blob.get(), &length));
  walker.size = length;
  if (walker.size < 34 || walker.read(0, 2) < 1) return layers;  // COLR v0 only
  if (const std::size_t root = walker.glyph_paint(glyph_id); root != 0) walker.walk(root, 0);
  return layers;
}

namespace {

double strike_ppem(FT_Face face, int strike) {
  return static_cast<double>(face->available_sizes[strike].y_ppem) / 64.0;
}

// The smallest strike of at least `ppem`, else the largest.
int choose_strike(FT_Face face, double ppem) {
  int best = -1, largest = 0;
  for (int i = 0; i < face->num_fixed_sizes; ++i) {
    const double size = strike_ppem(face, i);
    if (size > strike_ppem(face, largest)) largest = i;
    if (size >= ppem && (best < 0 || size < strike_ppem(face, best))) best = i;
  }
  return best >= 0 ? best : largest;
}

}  // namespace

std::vector<double> Font::color_bitmap_strikes() const {
  std::vector<double> strikes;
  if (impl_->color_format != ColorFormat::Bitmap) return strikes;
  const FT_Face face = impl_->ft_face;
  for (int i = 0; i < face->num_fixed_sizes; ++i) strikes.push_back(strike_ppem(face, i));
  return strikes;
}

ColorBitmap Font::color_bitmap(std::uint32_t glyph_id, double pixels_per_em) const {
  const Impl& im = *impl_;
  if (!(pixels_per_em > 0.0) || !std::isfinite(pixels_per_em))
    throw Error(ErrorCode::InvalidArgument, "a colour bitmap's size must be a positive number of pixels per em");
  check_glyph_id(glyph_id, im);
  ColorBitmap out;
  if (im.color_format != ColorFormat::Bitmap || im.ft_face->num_fixed_sizes <= 0) return out;
  std::lock_guard<std::mutex> lock(im.ft_mutex);
  const FT_Face face = im.ft_face;
  out.strike = choose_strike(face, pixels_per_em);
  out.strike_ppem = strike_ppem(face, out.strike);
  // Outlines load at the size where a font unit is a pixel (font.cpp's
  // set_unit_scale): put it back after the strike.
  struct RestoreScale {
    const Impl& im;
    ~RestoreScale() {
      if (FT_IS_SCALABLE(im.ft_face))
        FT_Set_Char_Size(im.ft_face, 0, static_cast<FT_F26Dot6>(im.units_per_em) * 64, 72, 72);
    }
  } restore{im};
  FT_Error error = FT_Select_Size(face, out.strike);
  if (error == 0) error = FT_Load_Glyph(face, glyph_id, FT_LOAD_COLOR);
  if (error != 0) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%02x", static_cast<unsigned>(error));
    throw Error(ErrorCode::FontInvalid,
                "cannot load the colour bitmap of " + glyph_text(glyph_id, im) + " (FreeType error " + code + ")");
  }
  const FT_GlyphSlot slot = face->glyph;
  const FT_Bitmap& bitmap = slot->bitmap;
  if (slot->format != FT_GLYPH_FORMAT_BITMAP || bitmap.width == 0 || bitmap.rows == 0) return out;  // 0 x 0
  if (bitmap.pixel_mode != FT_PIXEL_MODE_BGRA)
    throw Error(ErrorCode::FontInvalid, "the bitmap of " + glyph_text(glyph_id, im) + " is not a colour (BGRA) bitmap");
  if (bitmap.width > static_cast<unsigned>(tolerance::kMaxColorBitmapSidePx) ||
      bitmap.rows > static_cast<unsigned>(tolerance::kMaxColorBitmapSidePx))
    throw Error(ErrorCode::FontInvalid, "the colour bitmap of " + glyph_text(glyph_id, im) + " is " +
                                            std::to_string(bitmap.width) + "x" + std::to_string(bitmap.rows) +
                                            " px, over the limit of " +
                                            std::to_string(tolerance::kMaxColorBitmapSidePx) + " px a side");
  out.width = static_cast<int>(bitmap.width);
  out.height = static_cast<int>(bitmap.rows);
  out.left = slot->bitmap_left;
  out.top = slot->bitmap_top;
  out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  for (int y = 0; y < out.height; ++y) {
    const unsigned char* row = bitmap.buffer + static_cast<std::ptrdiff_t>(y) * bitmap.pitch;
    std::uint8_t* dst = &out.rgba[static_cast<std::size_t>(y) * out.width * 4];
    for (int x = 0; x < out.width; ++x) {  // BGRA (premultiplied) -> RGBA
      dst[4 * x + 0] = row[4 * x + 2];
      dst[4 * x + 1] = row[4 * x + 1];
      dst[4 * x + 2] = row[4 * x + 0];
      dst[4 * x + 3] = row[4 * x + 3];
    }
  }
  return out;
}

}  // namespace curvetext
