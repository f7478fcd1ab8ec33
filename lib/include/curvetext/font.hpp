// Fonts: one face of a font file (TrueType glyf, OpenType CFF/CFF2, a face of a
// .ttc/.otc collection), optionally at variation-axis values, read by FreeType
// and HarfBuzz from the same bytes. Outlines are in font units (y up), so one
// outline serves every size.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/color_glyph.hpp"
#include "curvetext/export.hpp"
#include "curvetext/outline.hpp"

namespace curvetext {

struct Variation {
  std::string tag;     // four characters, e.g. "wght"
  float value = 0.0f;  // in the axis's design units (wght: 100-900)
};

// Parses "wght=700,wdth=85" (spaces allowed; HarfBuzz's variation syntax
// without ranges); a blank text gives none. Throws Error(InvalidArgument)
// naming the bad item.
CURVETEXT_API std::vector<Variation> parse_variations(std::string_view text);

struct FontMetrics {
  int units_per_em = 0;
  // hb_font_get_h_extents at the current variation, in font units.
  double ascender = 0.0;
  double descender = 0.0;  // negative below the baseline
  double line_gap = 0.0;
  // Decoration bars, in font units at the current variation (MVAR applied),
  // positions y up from the baseline (negative below it); the bar is drawn
  // centred on its position. Underline: the post table's underlinePosition
  // and underlineThickness; strikeout: OS/2's yStrikeoutPosition and
  // yStrikeoutSize. A face without the table gets -0.1 em (underline) or
  // 0.3 em (strikeout) and a thickness of 0.05 em.
  double underline_position = 0.0;
  double underline_thickness = 0.0;
  double strikeout_position = 0.0;
  double strikeout_thickness = 0.0;
};

// Synthetic bold and slant for a face that lacks the weight or slant asked
// for (fontconfig's FC_EMBOLDEN and FC_MATRIX, as Pango draws them). Layout
// applies tolerance::kSyntheticEmboldenEm / kSyntheticSlant by the rule in
// docs/markup.md; zeros: the face as designed.
struct FontSynthesis {
  // Stroke growth in ems: every outline is offset outward as FreeType's
  // FT_Outline_EmboldenXY does with a strength of s = round(embolden_em *
  // units_per_em) font units (the left side and the baseline stay, the
  // right side and the top move out by s), and every non-zero horizontal
  // advance grows by s. 0 to tolerance::kMaxSyntheticEmboldenEm.
  double embolden_em = 0.0;
  // Shear after emboldening: x += slant * y for every outline point, and
  // x_offset += slant * y_offset for shaped glyphs (raised marks follow the
  // slant). -kMaxSyntheticSlant to kMaxSyntheticSlant.
  double slant = 0.0;
  friend bool operator==(const FontSynthesis& a, const FontSynthesis& b) {
    return a.embolden_em == b.embolden_em && a.slant == b.slant;
  }
  friend bool operator!=(const FontSynthesis& a, const FontSynthesis& b) { return !(a == b); }
};

// One face, owning a copy of the file's bytes (the file is not read again
// and may change or go after open) and its own FreeType and HarfBuzz state.
//
// Thread safety: the const member functions may be called from several
// threads at once (FreeType's use is serialised per font); set_variations,
// assignment and destruction need exclusive use. A moved-from Font may only
// be assigned to or destroyed. Fonts handed out as shared_ptr<const Font>
// (FontCollection, GlyphRun) are shared this way.
class CURVETEXT_API Font {
 public:
  // Reads the whole file. Throws Error(FontNotFound) if the file cannot be
  // read, Error(FontInvalid) if it is not a usable font (outlines, COLR
  // layers, or CBDT/sbix colour bitmaps) or face_index is out of range.
  static Font open(const std::string& path, int face_index = 0);
  // The same from font file bytes already in memory (an asset pack, an
  // embedded font). The bytes are copied: `data` need not outlive the call.
  // `name` stands for the path in error messages. Throws
  // Error(FontInvalid) if the bytes are not a usable scalable font or
  // face_index is out of range.
  static Font open_memory(std::span<const std::uint8_t> data, const std::string& name = "font in memory",
                          int face_index = 0);
  // Number of faces in a file (1 for a plain font file). Same errors as open.
  static int face_count(const std::string& path);

  Font(Font&&) noexcept;
  Font& operator=(Font&&) noexcept;
  ~Font();

  // Sets variation axis values for both FreeType and HarfBuzz; axes not
  // named go back to their defaults. Values are clamped to the axis range.
  // Throws Error(FontInvalid) naming the axis if the font has no such axis or
  // is not variable, Error(InvalidArgument) for a bad tag or a non-finite
  // value (the font is then unchanged, but for FreeType's own failure).
  // Changes cache_key(), so cached glyph meshes are never mixed up.
  void set_variations(const std::vector<Variation>& variations);
  // What set_variations was last given (clamped, one per axis named);
  // valid until the next set_variations.
  const std::vector<Variation>& variations() const;

  // Makes outlines, advances and glyph extents synthetic bold and/or slanted
  // (FontSynthesis); {} undoes it. Needs exclusive use, as set_variations.
  // Changes cache_key(). Throws Error(InvalidArgument) for a value out of
  // range or not finite, Error(FontInvalid) for a colour face (COLR layers or
  // bitmaps are drawn as designed: a synthetic colour glyph is refused, not
  // half drawn); the font is then unchanged.
  void set_synthesis(const FontSynthesis& synthesis);
  const FontSynthesis& synthesis() const;
  // The emboldening strength in font units (FontSynthesis::embolden_em).
  double synthetic_strength() const;

  const std::string& path() const;  // as given to open
  int face_index() const;
  std::string family_name() const;  // the face's family name; empty when it has none
  // A key that differs between faces, between variation settings and
  // between syntheses; used by the glyph cache. Equal for two Fonts opened
  // from the same path and face at the same (clamped) variations and
  // synthesis.
  std::uint64_t cache_key() const;

  // At the current variations, in font units.
  FontMetrics metrics() const;
  unsigned glyph_count() const;  // glyph ids are 0 .. glyph_count() - 1
  // Outline of a glyph in font units, unhinted, at the current variations,
  // emboldened and slanted by the synthesis (set_synthesis).
  // Empty outline for glyphs without contours (space). Throws Error(FontInvalid)
  // for glyph ids out of range or a glyph the font's data cannot give, and
  // for any glyph of a face whose glyphs are colour bitmaps only (see
  // color_bitmap).
  Outline glyph_outline(std::uint32_t glyph_id) const;
  // The same into `out`, which is cleared first (its storage is reused).
  void glyph_outline(std::uint32_t glyph_id, Outline& out) const;
  // Glyph id for a Unicode code point, 0 when the font has none.
  std::uint32_t glyph_for_codepoint(char32_t codepoint) const;

  // Colour glyphs (color_glyph.hpp).
  ColorFormat color_format() const;
  // A COLR glyph's layers in drawing order, from the first palette; empty
  // for a glyph without a colour record (draw its outline in the text's
  // colour) and in faces without COLR. COLR v1 paint graphs are followed
  // through layer lists, glyphs filled with a solid colour or a linear,
  // radial or sweep gradient (under static transforms inside the glyph) and
  // references to other colour glyphs; variable paints, composites and
  // transforms around a glyph are not drawn:
  // Error(FontInvalid) names the paint and the glyph, as it does a glyph id
  // out of range, a graph nested deeper than tolerance::kMaxColorPaintDepth,
  // one visiting more than kMaxColorPaints paints or one with more than
  // kMaxColorLayers layers.
  std::vector<ColorLayer> color_layers(std::uint32_t glyph_id) const;
  // The pixels per em of a bitmap colour font's strikes, in the font's
  // order; empty in faces without bitmaps.
  std::vector<double> color_bitmap_strikes() const;
  // A bitmap colour font's glyph from the smallest strike of at least
  // `pixels_per_em` (the largest strike when none is that large). Empty
  // (0 x 0) for a glyph without a bitmap and in faces without bitmaps.
  // Throws Error(InvalidArgument) for a size that is not positive and
  // finite, Error(FontInvalid) for a glyph id out of range, a bitmap that
  // cannot be decoded or one wider or taller than
  // tolerance::kMaxColorBitmapSidePx.
  ColorBitmap color_bitmap(std::uint32_t glyph_id, double pixels_per_em) const;

 private:
  friend struct FontAccess;  // lib/font/font_impl.hpp
  struct CURVETEXT_HIDDEN Impl;
  explicit Font(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvetext
