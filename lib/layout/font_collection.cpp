// Font lookup and fallback with fontconfig, cached per pattern and per
// character (see font_collection.hpp).

#include "curvetext/font_collection.hpp"

#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <optional>

#include "curvetext/default_font.hpp"
#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"
#include "font/face_queries.hpp"

namespace curvetext {

namespace {

FcConfig* config() {
  // FcInitLoadConfigAndFonts once per process; fontconfig's own global config
  // is reference counted and safe to keep for the process lifetime.
  static FcConfig* cfg = [] {
    FcInit();
    return FcConfigGetCurrent();
  }();
  return cfg;
}

std::string variations_key(const std::vector<Variation>& variations) {
  std::string key;
  for (const Variation& v : variations) key += v.tag + "=" + std::to_string(v.value) + ",";
  return key;
}

struct PatternDeleter {
  void operator()(FcPattern* p) const noexcept { FcPatternDestroy(p); }
};
using PatternPtr = std::unique_ptr<FcPattern, PatternDeleter>;

// "file.ttc#2" -> file, face 2; any other name -> itself, face 0.
std::pair<std::string, int> file_and_index(const std::string& name) {
  if (const std::size_t hash = name.rfind('#'); hash != std::string::npos && hash + 1 < name.size()) {
    const std::string digits = name.substr(hash + 1);
    if (digits.find_first_not_of("0123456789") == std::string::npos && digits.size() < 6)
      return {name.substr(0, hash), std::stoi(digits)};
  }
  return {name, 0};
}

bool is_file_name(const std::string& path) {
  std::error_code ec;
  return path.find('/') != std::string::npos || std::filesystem::exists(path, ec);
}

// "dir/file.ttf:weight=bold:slant=italic" -> the file and ":weight=bold:slant=italic":
// a font file followed by weight and slant properties only, the name as a
// whole not being a file.
std::optional<std::pair<std::string, std::string>> split_file_style(const std::string& name) {
  std::error_code ec;
  if (std::filesystem::exists(name, ec)) return std::nullopt;
  const std::size_t slash = name.rfind('/');
  const std::size_t colon = name.find(':', slash == std::string::npos ? 0 : slash + 1);
  if (colon == std::string::npos || colon == 0) return std::nullopt;
  for (std::size_t at = colon; at != std::string::npos;) {
    const std::size_t next = name.find(':', at + 1);
    const std::string item = name.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1);
    if (item.rfind("weight=", 0) != 0 && item.rfind("slant=", 0) != 0) return std::nullopt;
    at = next;
  }
  const std::string file = name.substr(0, colon);
  if (!is_file_name(file_and_index(file).first)) return std::nullopt;
  return std::make_pair(file, name.substr(colon));
}

// fontconfig's best match for a pattern, with the style the pattern asked
// for (as FontCollection::Match).
struct PatternMatch {
  std::string file;
  int index = -1;  // -1: none
  double weight = 0.0;
  bool slanted = false;
};

// With `family` not empty, only a face of that family counts.
PatternMatch match_pattern(FcPattern* pattern, const std::string& family);

}  // namespace

bool has_outlines(const Font& font) {
  for (hb_tag_t table : {HB_TAG('g', 'l', 'y', 'f'), HB_TAG('C', 'F', 'F', ' '), HB_TAG('C', 'F', 'F', '2')})
    if (detail::has_table(font, table)) return true;
  return false;
}

namespace {

// Faces fallback may take: with outlines or colour bitmaps; colour ones only
// (COLR or bitmaps) for emoji presentation.
bool drawable(const Font& font, bool color_only) {
  if (color_only) return font.color_format() != ColorFormat::None;
  return has_outlines(font) || font.color_format() == ColorFormat::Bitmap;
}

}  // namespace

FontCollection::FontCollection(std::string default_font) : default_path_(std::move(default_font)) {}
FontCollection::~FontCollection() = default;

std::shared_ptr<const Font> FontCollection::open_file(const std::string& path, int index,
                                                      const std::vector<Variation>& variations, bool strict,
                                                      const FontSynthesis& synthesis) {
  std::string key = path + "#" + std::to_string(index) + "|" + variations_key(variations);
  if (synthesis != FontSynthesis{})
    key += "|synthetic " + std::to_string(synthesis.embolden_em) + " " + std::to_string(synthesis.slant);
  if (auto it = by_key_.find(key); it != by_key_.end()) return it->second;
  // fontconfig names a variable font's named instance (Inter Bold) in the
  // index's upper 16 bits: the face at that instance's axis values, under
  // the ones asked for.
  auto font = std::make_shared<Font>(Font::open(path, index & 0xffff));
  ++stats_.faces;
  std::vector<Variation> values = variations;
  if (index >> 16 != 0) {
    values = detail::named_instance_variations(*font, index >> 16);
    for (const Variation& v : variations) {
      auto same = std::find_if(values.begin(), values.end(), [&](const Variation& w) { return w.tag == v.tag; });
      if (same != values.end()) *same = v;
    }
  }
  if (!values.empty()) {
    try {
      font->set_variations(values);
    } catch (const Error&) {
      // A fallback face without the span's axes is still the right face.
      if (strict) throw;
    }
  }
  font->set_synthesis(synthesis);
  std::shared_ptr<const Font> result = std::move(font);
  by_key_[key] = result;
  return result;
}

std::shared_ptr<const Font> FontCollection::default_font() {
  const std::string path = default_path_.empty() ? default_font_path("") : default_path_;
  return open_file(path, 0, {}, true);
}

std::shared_ptr<const Font> FontCollection::resolve(const std::string& name, const std::vector<Variation>& variations) {
  if (name.empty()) throw Error(ErrorCode::InvalidArgument, "empty font name");
  if (const auto styled = split_file_style(name)) return resolve_styled_file(styled->first, styled->second, variations);
  const auto [path, index] = file_and_index(name);
  if (is_file_name(path)) return open_file(path, index, variations, true);

  auto found = by_pattern_.find(name);
  if (found == by_pattern_.end()) {
    ++stats_.fontconfig_queries;
    PatternPtr pattern(FcNameParse(reinterpret_cast<const FcChar8*>(name.c_str())));
    if (!pattern) throw Error(ErrorCode::FontNotFound, "bad fontconfig pattern '" + name + "'");
    const PatternMatch m = match_pattern(pattern.get(), {});
    const Match match{m.file, m.index, m.weight, m.slanted};
    if (match.index < 0) throw Error(ErrorCode::FontNotFound, "no font matches '" + name + "' (fontconfig)");
    found = by_pattern_.emplace(name, match).first;
  }
  return synthesised(open_file(found->second.file, found->second.index, variations, true), found->second.weight,
                     found->second.slanted);
}

// The file's family in the style asked for where fontconfig has it: Pango
// would draw that face for the family. Else the file, synthesised.
std::shared_ptr<const Font> FontCollection::resolve_styled_file(const std::string& file, const std::string& style,
                                                                const std::vector<Variation>& variations) {
  const auto [path, index] = file_and_index(file);
  std::shared_ptr<const Font> face = open_file(path, index, variations, true);
  const std::string family = face->family_name();
  const std::string key = family + "\n" + style;  // no pattern holds a newline
  auto found = by_pattern_.find(key);
  if (found == by_pattern_.end()) {
    ++stats_.fontconfig_queries;
    PatternPtr pattern(FcNameParse(reinterpret_cast<const FcChar8*>(style.c_str())));
    if (!pattern) throw Error(ErrorCode::FontNotFound, "bad font style '" + style + "' for " + file);
    if (!family.empty()) FcPatternAddString(pattern.get(), FC_FAMILY, reinterpret_cast<const FcChar8*>(family.c_str()));
    const PatternMatch m = match_pattern(pattern.get(), family);
    found = by_pattern_.emplace(key, Match{m.file, m.index, m.weight, m.slanted}).first;
  }
  const Match& match = found->second;
  if (!family.empty() && match.index >= 0) face = open_file(match.file, match.index, variations, true);
  return synthesised(face, match.weight, match.slanted);
}

// docs/markup.md, "Synthetic bold and italic": a face lighter than the
// weight asked for by more than 150 (of a bold one: 600 or more) is
// emboldened, an upright face asked to be italic or oblique is slanted.
// Colour faces stay as designed.
std::shared_ptr<const Font> FontCollection::synthesised(const std::shared_ptr<const Font>& face, double weight,
                                                        bool italic) {
  if (face->color_format() != ColorFormat::None) return face;
  FontSynthesis synthesis = face->synthesis();
  if (weight >= 600.0 && detail::style_value(*face, HB_STYLE_TAG_WEIGHT) < weight - 150.0)
    synthesis.embolden_em = tolerance::kSyntheticEmboldenEm;
  if (italic && detail::style_value(*face, HB_STYLE_TAG_ITALIC) == 0.0f &&
      detail::style_value(*face, HB_STYLE_TAG_SLANT_RATIO) == 0.0f)
    synthesis.slant = tolerance::kSyntheticSlant;
  if (synthesis == face->synthesis()) return face;
  return open_file(face->path(), face->face_index(), face->variations(), true, synthesis);
}

bool FontCollection::has_glyph(const Font& font, char32_t c) {
  if (c > 0xFFFF) return font.glyph_for_codepoint(c) != 0;
  // The same face is asked about many characters in a row: skip the map.
  if (&font != last_font_) {
    last_coverage_ = &coverage_[&font];  // element addresses survive rehashing
    last_font_ = &font;
  }
  Coverage& cov = *last_coverage_;
  if (cov.known.empty()) {
    cov.known.assign(0x10000 / 64, 0);
    cov.has.assign(0x10000 / 64, 0);
  }
  const std::size_t word = c / 64;
  const std::uint64_t bit = std::uint64_t{1} << (c % 64);
  if (!(cov.known[word] & bit)) {
    cov.known[word] |= bit;
    if (font.glyph_for_codepoint(c) != 0) cov.has[word] |= bit;
  }
  return (cov.has[word] & bit) != 0;
}

std::shared_ptr<const Font> FontCollection::fallback(char32_t c, const std::string& language,
                                                     const std::vector<Variation>& variations) {
  return find_fallback(c, language, variations, false);
}

std::shared_ptr<const Font> FontCollection::color_fallback(char32_t c, const std::string& language) {
  return find_fallback(c, language, {}, true);
}

std::shared_ptr<const Font> FontCollection::find_fallback(char32_t c, const std::string& language,
                                                          const std::vector<Variation>& variations, bool color_only) {
  const std::string key = std::to_string(static_cast<unsigned long>(c)) + "|" + language + "|" +
                          variations_key(variations) + (color_only ? "|colour" : "");
  if (auto it = fallback_.find(key); it != fallback_.end()) {
    ++stats_.fallback_hits;
    return it->second;
  }
  // Faces already used for fallback first: a CJK paragraph then needs one
  // fontconfig query, not one per ideograph. Not a bitmap emoji face for
  // other fallback, though: text presentation keeps fontconfig's order.
  for (const auto& face : fallback_faces_)
    if ((color_only ? face->color_format() != ColorFormat::None : face->color_format() != ColorFormat::Bitmap) &&
        face->glyph_for_codepoint(c) != 0) {
      std::shared_ptr<const Font> f = face;
      if (!variations.empty()) f = open_file(face->path(), face->face_index(), variations, false);
      fallback_[key] = f;
      return f;
    }

  ++stats_.fontconfig_queries;
  std::shared_ptr<const Font> chosen;
  PatternPtr pattern(FcPatternCreate());
  FcCharSet* charset = FcCharSetCreate();
  FcCharSetAddChar(charset, static_cast<FcChar32>(c));
  FcPatternAddCharSet(pattern.get(), FC_CHARSET, charset);
  FcCharSetDestroy(charset);
  FcPatternAddBool(pattern.get(), FC_SCALABLE, FcTrue);
  if (!language.empty()) FcPatternAddString(pattern.get(), FC_LANG, reinterpret_cast<const FcChar8*>(language.c_str()));
  FcConfigSubstitute(config(), pattern.get(), FcMatchPattern);
  FcDefaultSubstitute(pattern.get());
  FcResult result = FcResultNoMatch;
  FcFontSet* set = FcFontSort(config(), pattern.get(), FcFalse, nullptr, &result);
  if (set) {
    for (int i = 0; i < set->nfont && !chosen; ++i) {
      FcPattern* font = set->fonts[i];
      FcCharSet* cs = nullptr;
      if (FcPatternGetCharSet(font, FC_CHARSET, 0, &cs) != FcResultMatch || !FcCharSetHasChar(cs, c)) continue;
      FcBool color = FcFalse;
      if (color_only && (FcPatternGetBool(font, FC_COLOR, 0, &color) != FcResultMatch || !color)) continue;
      FcChar8* file = nullptr;
      int index = 0;
      if (FcPatternGetString(font, FC_FILE, 0, &file) != FcResultMatch) continue;
      FcPatternGetInteger(font, FC_INDEX, 0, &index);
      try {
        auto face = open_file(reinterpret_cast<const char*>(file), index, {}, false);
        if (!drawable(*face, color_only) || face->glyph_for_codepoint(c) == 0) continue;
        fallback_faces_.push_back(face);
        chosen = variations.empty() ? face : open_file(face->path(), index, variations, false);
      } catch (const Error&) {
        continue;  // unreadable or not scalable: try the next
      }
    }
    FcFontSetDestroy(set);
  }
  fallback_[key] = chosen;
  return chosen;
}

namespace {

// The style a pattern asks for, read before fontconfig fills in defaults.
void read_style(FcPattern* pattern, PatternMatch& match) {
  double weight = 0.0;
  int integer = 0;
  if (FcPatternGetDouble(pattern, FC_WEIGHT, 0, &weight) == FcResultMatch)
    match.weight = FcWeightToOpenTypeDouble(weight);
  else if (FcPatternGetInteger(pattern, FC_WEIGHT, 0, &integer) == FcResultMatch)
    match.weight = FcWeightToOpenTypeDouble(integer);
  if (FcPatternGetInteger(pattern, FC_SLANT, 0, &integer) == FcResultMatch) match.slanted = integer != FC_SLANT_ROMAN;
}

bool has_family(FcPattern* font, const std::string& family) {
  FcChar8* name = nullptr;
  for (int i = 0; FcPatternGetString(font, FC_FAMILY, i, &name) == FcResultMatch; ++i)
    if (FcStrCmpIgnoreCase(name, reinterpret_cast<const FcChar8*>(family.c_str())) == 0) return true;
  return false;
}

PatternMatch match_pattern(FcPattern* pattern, const std::string& family) {
  PatternMatch match;
  read_style(pattern, match);
  FcPatternAddBool(pattern, FC_SCALABLE, FcTrue);
  FcConfigSubstitute(config(), pattern, FcMatchPattern);
  FcDefaultSubstitute(pattern);
  FcResult result = FcResultNoMatch;
  PatternPtr found(FcFontMatch(config(), pattern, &result));
  FcChar8* file = nullptr;
  if (!found || FcPatternGetString(found.get(), FC_FILE, 0, &file) != FcResultMatch) return match;
  if (!family.empty() && !has_family(found.get(), family)) return match;
  match.file = reinterpret_cast<const char*>(file);
  match.index = 0;
  FcPatternGetInteger(found.get(), FC_INDEX, 0, &match.index);
  return match;
}

}  // namespace

}  // namespace curvetext
