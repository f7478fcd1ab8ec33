// Colour glyphs (color_glyph.hpp): COLR v0 layers and CBDT/sbix bitmaps read
// by FreeType, and the solid-colour subset of COLR v1 paint graphs read here.

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_COLOR_H
#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "curvetext/error.hpp"
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
  if (format == 4 || format == 5) return "a linear gradient (PaintLinearGradient)";
  if (format == 6 || format == 7) return "a radial gradient (PaintRadialGradient)";
  if (format == 8 || format == 9) return "a sweep gradient (PaintSweepGradient)";
  if (format >= 12 && format <= 31) return "a transformed paint (PaintTransform, Translate, Scale, Rotate or Skew)";
  if (format == 32) return "a composite (PaintComposite)";
  return "paint format " + std::to_string(format) + ", which OpenType does not define";
}

// Reads the COLR table's v1 paint graphs itself: Debian 12's FreeType is
// built with its COLR v1 API disabled (it returns no paint for any glyph),
// and HarfBuzz 6 has none. Every read is bounds-checked against the table.
// Supported: layer lists, glyphs filled with a solid colour, references to
// other colour glyphs; anything else is refused by name.
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
      const std::size_t fill = paint + read(paint + 1, 3);
      const unsigned fill_format = read(fill, 1);
      if (fill_format != 2) refuse(paint_name(fill_format) + " is not supported yet (solid fills are)");
      const std::int16_t alpha = static_cast<std::int16_t>(read(fill + 3, 2));  // F2DOT14
      add(solid(read(paint + 4, 2), read(fill + 1, 2), alpha / 16384.0));
    } else if (format == 11) {  // PaintColrGlyph: glyphID u16
      const std::uint32_t glyph = read(paint + 1, 2);
      const std::size_t inner = glyph_paint(glyph);
      if (inner == 0) refuse("PaintColrGlyph names glyph " + std::to_string(glyph) + ", which has no paint");
      walk(inner, depth + 1);
    } else if (format == 2) {
      refuse("a solid paint outside a glyph (filling the whole clip box) is not supported yet");
    } else {
      refuse(paint_name(format) + " is not supported yet (solid fills are)");
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
