// The one place HarfBuzz's glyph output is read (see shaper.hpp).

#include "font/shaper.hpp"

#include <new>

#include "font/harfbuzz_font.hpp"

namespace curvetext::detail {

void Shaper::BufferDeleter::operator()(hb_buffer_t* buffer) const noexcept { hb_buffer_destroy(buffer); }

Shaper::Shaper() : buffer_(hb_buffer_create()) {
  if (!hb_buffer_allocation_successful(buffer_.get())) throw std::bad_alloc();
}

Shaper::~Shaper() = default;

hb_buffer_t* Shaper::prepare(const ShapeSettings& settings) {
  hb_buffer_t* buf = buffer_.get();
  hb_buffer_reset(buf);
  if (settings.direction != HB_DIRECTION_INVALID) hb_buffer_set_direction(buf, settings.direction);
  if (settings.script != HB_SCRIPT_INVALID) hb_buffer_set_script(buf, settings.script);
  if (settings.language != HB_LANGUAGE_INVALID) hb_buffer_set_language(buf, settings.language);
  unsigned flags = HB_BUFFER_FLAG_DEFAULT;
  if (settings.beginning_of_text) flags |= HB_BUFFER_FLAG_BOT;
  if (settings.end_of_text) flags |= HB_BUFFER_FLAG_EOT;
  hb_buffer_set_flags(buf, static_cast<hb_buffer_flags_t>(flags));
  return buf;
}

std::span<const UnitGlyph> Shaper::shape(const Font& font, std::u32string_view text, std::size_t start,
                                         std::size_t length, const ShapeSettings& settings) {
  hb_buffer_t* buf = prepare(settings);
  hb_buffer_add_utf32(buf, reinterpret_cast<const std::uint32_t*>(text.data()), static_cast<int>(text.size()),
                      static_cast<unsigned>(start), static_cast<int>(length));
  return run(font, settings);
}

std::span<const UnitGlyph> Shaper::shape(const Font& font, std::string_view utf8, const ShapeSettings& settings) {
  hb_buffer_t* buf = prepare(settings);
  // Clusters start as the byte offset of each character (item_offset 0).
  const char* data = utf8.empty() ? "" : utf8.data();
  hb_buffer_add_utf8(buf, data, static_cast<int>(utf8.size()), 0, static_cast<int>(utf8.size()));
  return run(font, settings);
}

std::span<const UnitGlyph> Shaper::run(const Font& font, const ShapeSettings& settings) {
  hb_buffer_t* buf = buffer_.get();
  if (settings.guess_unset) hb_buffer_guess_segment_properties(buf);  // fills only what is unset
  hb_shape(harfbuzz_font(font), buf, settings.features.data(), static_cast<unsigned>(settings.features.size()));
  if (!hb_buffer_allocation_successful(buf)) throw std::bad_alloc();
  unsigned count = 0;
  const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf, &count);
  const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &count);
  const double slant = font.synthesis().slant;
  glyphs_.resize(count);
  for (unsigned i = 0; i < count; ++i) {
    UnitGlyph& g = glyphs_[i];
    g.id = info[i].codepoint;
    g.cluster = info[i].cluster;
    g.x_advance = pos[i].x_advance;
    g.y_advance = pos[i].y_advance;
    g.x_offset = pos[i].x_offset + slant * pos[i].y_offset;
    g.y_offset = pos[i].y_offset;
    g.unsafe_to_break = (hb_glyph_info_get_glyph_flags(&info[i]) & HB_GLYPH_FLAG_UNSAFE_TO_BREAK) != 0;
  }
  return {glyphs_.data(), glyphs_.size()};
}

}  // namespace curvetext::detail
