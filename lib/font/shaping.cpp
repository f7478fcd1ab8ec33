// Shaping one line with HarfBuzz at a scale of units_per_em, so every
// position is in font units and the caller scales to pixels without rounding.

#include <algorithm>
#include <cctype>
#include <climits>
#include <new>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/shaping.hpp"
#include "font/harfbuzz_font.hpp"
#include "font/option_lists.hpp"

namespace curvetext {

namespace {

using detail::trim;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Feature tags are 1-4 printable ASCII characters; OpenType pads to four with
// spaces (hb_tag_from_string does the padding).
hb_tag_t feature_tag(const std::string& tag) {
  const std::string_view t = trim(tag);
  bool ok = !t.empty() && t.size() <= 4;
  for (char c : t) ok = ok && c > 0x20 && c < 0x7f;
  if (!ok) throw Error(ErrorCode::InvalidArgument, "bad OpenType feature tag '" + tag + "'");
  return hb_tag_from_string(t.data(), static_cast<int>(t.size()));
}

}  // namespace

std::vector<Feature> parse_features(std::string_view text) {
  std::vector<Feature> result;
  for (const std::string_view item : detail::split_comma_list(text)) {
    hb_feature_t feature{};
    if (item.empty() || !hb_feature_from_string(item.data(), static_cast<int>(item.size()), &feature))
      throw Error(ErrorCode::InvalidArgument, "bad OpenType feature '" + std::string(item) + "' in '" +
                                                  std::string(text) + "' (expected e.g. kern, -liga, aalt=2)");
    // Feature carries no character range, so "kern[3:5]" cannot be honoured;
    // refuse it rather than apply it to the whole line.
    if (feature.start != HB_FEATURE_GLOBAL_START || feature.end != HB_FEATURE_GLOBAL_END)
      throw Error(ErrorCode::InvalidArgument,
                  "feature ranges are not supported: '" + std::string(item) + "' (apply it to the whole line)");
    char tag[4];
    hb_tag_to_string(feature.tag, tag);
    result.push_back({std::string(tag, 4), feature.value});
  }
  return result;
}

ShapedLine shape_line(const Font& font, std::string_view utf8, const ShapeOptions& options) {
  validate_utf8(utf8);
  if (utf8.size() > static_cast<std::size_t>(INT_MAX))
    throw Error(ErrorCode::InvalidText, "text too long to shape (" + std::to_string(utf8.size()) + " bytes)");

  std::vector<hb_feature_t> features;
  features.reserve(options.features.size());
  for (const Feature& f : options.features)
    features.push_back({feature_tag(f.tag), f.value, HB_FEATURE_GLOBAL_START, HB_FEATURE_GLOBAL_END});

  detail::HbBufferPtr buffer(hb_buffer_create());
  hb_buffer_t* buf = buffer.get();
  if (!hb_buffer_allocation_successful(buf)) throw std::bad_alloc();

  if (!options.direction.empty()) {
    const std::string d = lower(trim(options.direction));
    // hb_direction_from_string accepts any word starting with l/r/t/b; we
    // only take the four documented names so typos are caught.
    if (d != "ltr" && d != "rtl" && d != "ttb" && d != "btt")
      throw Error(ErrorCode::InvalidArgument, "bad text direction '" + options.direction + "' (ltr, rtl, ttb or btt)");
    hb_buffer_set_direction(buf, hb_direction_from_string(d.data(), static_cast<int>(d.size())));
  }
  if (!options.script.empty()) {
    const std::string_view s = trim(options.script);
    const bool ok = s.size() == 4 && std::all_of(s.begin(), s.end(), [](char c) {
                      return std::isalpha(static_cast<unsigned char>(c)) != 0;
                    });
    if (!ok) throw Error(ErrorCode::InvalidArgument, "bad ISO 15924 script code '" + options.script + "' (e.g. Latn)");
    hb_buffer_set_script(buf, hb_script_from_string(s.data(), static_cast<int>(s.size())));
  }
  if (!options.language.empty()) {
    const std::string_view l = trim(options.language);
    hb_language_t language = hb_language_from_string(l.data(), static_cast<int>(l.size()));
    if (language == HB_LANGUAGE_INVALID)
      throw Error(ErrorCode::InvalidArgument, "bad BCP 47 language tag '" + options.language + "'");
    hb_buffer_set_language(buf, language);
  }
  // The line is the whole text HarfBuzz will see: mark both ends so joining
  // scripts and contextual rules treat them as text boundaries.
  hb_buffer_set_flags(buf, static_cast<hb_buffer_flags_t>(HB_BUFFER_FLAG_BOT | HB_BUFFER_FLAG_EOT));
  // Clusters start as the byte offset of each character (item_offset 0).
  const char* data = utf8.empty() ? "" : utf8.data();
  hb_buffer_add_utf8(buf, data, static_cast<int>(utf8.size()), 0, static_cast<int>(utf8.size()));
  hb_buffer_guess_segment_properties(buf);  // fills only what was not set above

  hb_shape(harfbuzz_font(font), buf, features.data(), static_cast<unsigned int>(features.size()));
  if (!hb_buffer_allocation_successful(buf)) throw std::bad_alloc();

  unsigned int count = 0;
  const hb_glyph_info_t* infos = hb_buffer_get_glyph_infos(buf, &count);
  const hb_glyph_position_t* positions = hb_buffer_get_glyph_positions(buf, &count);
  const double slant = font.synthesis().slant;  // raised marks follow a synthetic slant
  ShapedLine line;
  line.glyphs.reserve(count);
  for (unsigned int i = 0; i < count; ++i) {
    ShapedGlyph g;
    g.glyph_id = infos[i].codepoint;
    g.cluster = infos[i].cluster;
    g.x_offset = positions[i].x_offset + slant * positions[i].y_offset;
    g.y_offset = positions[i].y_offset;
    g.x_advance = positions[i].x_advance;
    g.y_advance = positions[i].y_advance;
    line.advance += g.x_advance;
    line.glyphs.push_back(g);
  }
  return line;
}

}  // namespace curvetext
