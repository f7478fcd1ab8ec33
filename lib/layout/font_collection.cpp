// Font lookup and fallback with fontconfig, cached per pattern and per
// character (see font_collection.hpp).

#include "curvetext/font_collection.hpp"

#include <fontconfig/fontconfig.h>

#include <filesystem>
#include <mutex>

#include "curvetext/default_font.hpp"
#include "curvetext/error.hpp"
#include "font/harfbuzz_font.hpp"

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

}  // namespace

bool has_outlines(const Font& font) {
  hb_face_t* face = hb_font_get_face(harfbuzz_font(font));
  for (hb_tag_t table : {HB_TAG('g', 'l', 'y', 'f'), HB_TAG('C', 'F', 'F', ' '), HB_TAG('C', 'F', 'F', '2')}) {
    const detail::HbBlobPtr blob(hb_face_reference_table(face, table));
    if (hb_blob_get_length(blob.get()) > 0) return true;
  }
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
                                                      const std::vector<Variation>& variations, bool strict) {
  const std::string key = path + "#" + std::to_string(index) + "|" + variations_key(variations);
  if (auto it = by_key_.find(key); it != by_key_.end()) return it->second;
  auto font = std::make_shared<Font>(Font::open(path, index));
  ++stats_.faces;
  if (!variations.empty()) {
    try {
      font->set_variations(variations);
    } catch (const Error&) {
      // A fallback face without the span's axes is still the right face.
      if (strict) throw;
    }
  }
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
  std::string path = name;
  int index = 0;
  // "file.ttc#2": a face of a collection.
  if (const std::size_t hash = name.rfind('#'); hash != std::string::npos && hash + 1 < name.size()) {
    const std::string digits = name.substr(hash + 1);
    if (digits.find_first_not_of("0123456789") == std::string::npos && digits.size() < 6) {
      path = name.substr(0, hash);
      index = std::stoi(digits);
    }
  }
  std::error_code ec;
  if (path.find('/') != std::string::npos || std::filesystem::exists(path, ec))
    return open_file(path, index, variations, true);

  auto found = by_pattern_.find(name);
  if (found == by_pattern_.end()) {
    ++stats_.fontconfig_queries;
    PatternPtr pattern(FcNameParse(reinterpret_cast<const FcChar8*>(name.c_str())));
    if (!pattern) throw Error(ErrorCode::FontNotFound, "bad fontconfig pattern '" + name + "'");
    FcPatternAddBool(pattern.get(), FC_SCALABLE, FcTrue);
    FcConfigSubstitute(config(), pattern.get(), FcMatchPattern);
    FcDefaultSubstitute(pattern.get());
    FcResult result = FcResultNoMatch;
    PatternPtr match(FcFontMatch(config(), pattern.get(), &result));
    FcChar8* file = nullptr;
    int face = 0;
    if (!match || FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch)
      throw Error(ErrorCode::FontNotFound, "no font matches '" + name + "' (fontconfig)");
    FcPatternGetInteger(match.get(), FC_INDEX, 0, &face);
    found = by_pattern_.emplace(name, std::make_pair(std::string(reinterpret_cast<const char*>(file)), face)).first;
  }
  return open_file(found->second.first, found->second.second, variations, true);
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

}  // namespace curvetext
