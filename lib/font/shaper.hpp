// Private interface of font/ for the stages after it: font/'s one way of
// shaping text, for font/ itself (shape_line) and for paragraph layout.
// HarfBuzz's glyph output is read here only: glyphs come back in font units
// (HarfBuzz runs at a scale of units_per_em, so nothing is rounded), with a
// synthetic slant applied to the offsets, and the caller scales them.
#pragma once

#include <hb.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "curvetext/font.hpp"

namespace curvetext::detail {

// One glyph as shaped, in font units, in HarfBuzz's order (visual order of
// the run: left to right for LTR, right to left for RTL text).
struct UnitGlyph {
  std::uint32_t id = 0;
  std::uint32_t cluster = 0;  // as given to the shaper: a byte or code point index
  double x_advance = 0.0, y_advance = 0.0;
  // x_offset includes synthesis().slant * y_offset: raised marks follow a
  // synthetic slant.
  double x_offset = 0.0, y_offset = 0.0;
  // HB_GLYPH_FLAG_UNSAFE_TO_BREAK: text cut before this glyph's cluster must
  // be shaped again.
  bool unsafe_to_break = false;
};

// What a shaping call sets on HarfBuzz's buffer. Unset properties
// (HB_DIRECTION_INVALID, HB_SCRIPT_INVALID, HB_LANGUAGE_INVALID) are guessed
// from the text when `guess_unset` is true and left unset otherwise.
struct ShapeSettings {
  hb_direction_t direction = HB_DIRECTION_INVALID;
  hb_script_t script = HB_SCRIPT_INVALID;
  hb_language_t language = HB_LANGUAGE_INVALID;
  std::span<const hb_feature_t> features;
  bool guess_unset = false;
  // The run starts / ends the text (HB_BUFFER_FLAG_BOT / EOT): joining
  // scripts and contextual rules treat that end as a text boundary.
  bool beginning_of_text = false;
  bool end_of_text = false;
};

// Shapes runs of text with one reusable HarfBuzz buffer (creating a buffer
// per run allocated its glyph arrays again every time). Not for use from
// several threads at once; one per thread or per layout.
class Shaper {
 public:
  Shaper();
  ~Shaper();
  Shaper(const Shaper&) = delete;
  Shaper& operator=(const Shaper&) = delete;

  // Shapes code points text[start, start + length), the rest of `text` being
  // context (Arabic joins across runs); clusters are indices into `text`.
  // The glyphs are valid until the next call.
  std::span<const UnitGlyph> shape(const Font& font, std::u32string_view text, std::size_t start, std::size_t length,
                                   const ShapeSettings& settings);
  // Shapes all of `utf8` (valid UTF-8, at most INT_MAX bytes); clusters are
  // byte offsets.
  std::span<const UnitGlyph> shape(const Font& font, std::string_view utf8, const ShapeSettings& settings);

 private:
  struct BufferDeleter {
    void operator()(hb_buffer_t* buffer) const noexcept;
  };
  hb_buffer_t* prepare(const ShapeSettings& settings);
  std::span<const UnitGlyph> run(const Font& font, const ShapeSettings& settings);

  std::unique_ptr<hb_buffer_t, BufferDeleter> buffer_;
  std::vector<UnitGlyph> glyphs_;
};

}  // namespace curvetext::detail
