// Face queries for the stages after font/ (face_queries.hpp).

#include "font/face_queries.hpp"

#include "font/harfbuzz_font.hpp"

namespace curvetext::detail {

float style_value(const Font& font, hb_style_tag_t tag) { return hb_style_get_value(harfbuzz_font(font), tag); }

double glyph_h_advance(const Font& font, std::uint32_t glyph) {
  return hb_font_get_glyph_h_advance(harfbuzz_font(font), glyph);
}

bool glyph_extents(const Font& font, std::uint32_t glyph, hb_glyph_extents_t& extents) {
  return hb_font_get_glyph_extents(harfbuzz_font(font), glyph, &extents) != 0;
}

bool has_table(const Font& font, hb_tag_t tag) {
  const HbBlobPtr blob(hb_face_reference_table(hb_font_get_face(harfbuzz_font(font)), tag));
  return hb_blob_get_length(blob.get()) > 0;
}

}  // namespace curvetext::detail
