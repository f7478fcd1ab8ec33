// Shaping one line with HarfBuzz at a scale of units_per_em, so every
// position is in font units and the caller scales to pixels without rounding.

#include <algorithm>
#include <cctype>
#include <climits>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/shaping.hpp"
#include "font/option_lists.hpp"
#include "font/shaper.hpp"

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

  detail::ShapeSettings settings;
  settings.features = features;
  // The line is the whole text HarfBuzz will see: both ends are text
  // boundaries for joining scripts and contextual rules.
  settings.beginning_of_text = settings.end_of_text = true;
  settings.guess_unset = true;
  if (!options.direction.empty()) {
    const std::string d = lower(trim(options.direction));
    // hb_direction_from_string accepts any word starting with l/r/t/b; we
    // only take the four documented names so typos are caught.
    if (d != "ltr" && d != "rtl" && d != "ttb" && d != "btt")
      throw Error(ErrorCode::InvalidArgument, "bad text direction '" + options.direction + "' (ltr, rtl, ttb or btt)");
    settings.direction = hb_direction_from_string(d.data(), static_cast<int>(d.size()));
  }
  if (!options.script.empty()) {
    const std::string_view s = trim(options.script);
    const bool ok = s.size() == 4 && std::all_of(s.begin(), s.end(), [](char c) {
                      return std::isalpha(static_cast<unsigned char>(c)) != 0;
                    });
    if (!ok) throw Error(ErrorCode::InvalidArgument, "bad ISO 15924 script code '" + options.script + "' (e.g. Latn)");
    settings.script = hb_script_from_string(s.data(), static_cast<int>(s.size()));
  }
  if (!options.language.empty()) {
    const std::string_view l = trim(options.language);
    settings.language = hb_language_from_string(l.data(), static_cast<int>(l.size()));
    if (settings.language == HB_LANGUAGE_INVALID)
      throw Error(ErrorCode::InvalidArgument, "bad BCP 47 language tag '" + options.language + "'");
  }

  detail::Shaper shaper;
  ShapedLine line;
  const std::span<const detail::UnitGlyph> glyphs = shaper.shape(font, utf8, settings);
  line.glyphs.reserve(glyphs.size());
  for (const detail::UnitGlyph& u : glyphs) {
    ShapedGlyph g;
    g.glyph_id = u.id;
    g.cluster = u.cluster;
    g.x_offset = u.x_offset;
    g.y_offset = u.y_offset;
    g.x_advance = u.x_advance;
    g.y_advance = u.y_advance;
    line.advance += g.x_advance;
    line.glyphs.push_back(g);
  }
  return line;
}

}  // namespace curvetext
