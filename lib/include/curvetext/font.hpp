// Fonts: one face of a font file (TrueType glyf, OpenType CFF/CFF2, a face of a
// .ttc/.otc collection), optionally at variation-axis values, read by FreeType
// and HarfBuzz from the same bytes. Outlines are in font units (y up), so one
// outline serves every size.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/outline.hpp"

namespace curvetext {

struct Variation {
  std::string tag;  // four characters, e.g. "wght"
  float value = 0.0f;
};

// Parses "wght=700,wdth=85" (spaces allowed). Throws Error(InvalidArgument).
std::vector<Variation> parse_variations(std::string_view text);

struct FontMetrics {
  int units_per_em = 0;
  // hb_font_get_h_extents at the current variation, in font units.
  double ascender = 0.0;
  double descender = 0.0;  // negative below the baseline
  double line_gap = 0.0;
};

class Font {
 public:
  // Throws Error(FontNotFound) if the file cannot be read, Error(FontInvalid)
  // if it is not a usable scalable font or face_index is out of range.
  static Font open(const std::string& path, int face_index = 0);
  // Number of faces in a file (1 for a plain font file).
  static int face_count(const std::string& path);

  Font(Font&&) noexcept;
  Font& operator=(Font&&) noexcept;
  ~Font();

  // Sets variation axis values for both FreeType and HarfBuzz. Throws
  // Error(FontInvalid) naming the axis if the font has no such axis or is not
  // variable. Values are clamped to the axis range.
  void set_variations(const std::vector<Variation>& variations);
  const std::vector<Variation>& variations() const;

  const std::string& path() const;
  int face_index() const;
  std::string family_name() const;
  // A key that differs between faces and between variation settings; used by
  // the glyph cache.
  std::uint64_t cache_key() const;

  FontMetrics metrics() const;
  unsigned glyph_count() const;
  // Outline of a glyph in font units, unhinted, at the current variations.
  // Empty outline for glyphs without contours (space). Throws Error(FontInvalid)
  // for glyph ids out of range.
  Outline glyph_outline(std::uint32_t glyph_id) const;
  // The same into `out`, which is cleared first (its storage is reused).
  void glyph_outline(std::uint32_t glyph_id, Outline& out) const;
  // Glyph id for a Unicode code point, 0 when the font has none.
  std::uint32_t glyph_for_codepoint(char32_t codepoint) const;

  // Access for the shaper and for FreeType-based reference rendering.
  struct Impl;
  Impl& impl() const { return *impl_; }

 private:
  explicit Font(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvetext
