// Fonts for layout: opening faces by file or by fontconfig family name, and
// font fallback (a face that covers a character), all cached, so a paragraph
// of thousands of CJK ideographs costs one fontconfig query per font, not per
// character.
//
// Faces with outlines (glyf, CFF or CFF2, with or without COLR layers) and
// colour bitmap faces (CBDT/CBLC like Noto Color Emoji, sbix) are used, the
// latter drawn from their bitmaps (color_glyph.hpp). Layout asks for a colour
// face first for emoji presentation (color_fallback); when no face covers a
// character, the first font's missing glyph (.notdef) is drawn.
//
// Not thread-safe: use one collection per thread (fonts handed out are
// immutable and may be shared, font.hpp). The collection keeps every face it
// opened until it is destroyed; the faces handed out live as long as their
// last shared_ptr.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "curvetext/export.hpp"
#include "curvetext/font.hpp"

namespace curvetext {

class CURVETEXT_API FontCollection {
 public:
  // `default_font`: the file used when a style names no font (empty: the
  // library's default font, DejaVu Sans). Opens nothing yet; does not throw.
  explicit FontCollection(std::string default_font = {});
  ~FontCollection();
  FontCollection(const FontCollection&) = delete;
  FontCollection& operator=(const FontCollection&) = delete;

  // A font file (a path with '/' or an existing file; "file.ttc#2" picks a
  // face) or a fontconfig pattern ("Noto Sans", "DejaVu Serif:bold"), at the
  // given variations; the same face again for the same name and variations.
  // A font file may ask for a style as a pattern does ("file.ttf:weight=bold",
  // ":slant=italic", both): the face of the file's family that fontconfig has
  // in that style, else the file's own face. A face lacking the weight or
  // slant asked for comes synthesised (Font::set_synthesis; the rule is in
  // docs/markup.md). Throws Error(InvalidArgument) for an empty name,
  // Error(FontNotFound) when fontconfig has no match or a style cannot be
  // read, and the font errors of Font::open / set_variations.
  std::shared_ptr<const Font> resolve(const std::string& name, const std::vector<Variation>& variations = {});
  // `face` in `weight` (OpenType, 1 to 1000; 0: as it is) and italic where
  // it lacks them, by the rule in docs/markup.md: `face` itself when it has
  // them or is a colour face, else a copy of it at its variations made
  // synthetic bold and/or slanted (Font::set_synthesis), kept like the faces
  // resolve opens. The copy is opened from face->path(): a face opened from
  // memory has no file to read again (Error(FontNotFound)); synthesise it
  // with Font::set_synthesis instead. Throws the errors of Font::open.
  std::shared_ptr<const Font> synthesised(const std::shared_ptr<const Font>& face, double weight, bool italic);
  // The constructor's default font (opened once). Throws the errors of
  // default_font_path (default_font.hpp) and Font::open.
  std::shared_ptr<const Font> default_font();

  // A face with outlines or colour bitmaps that has a glyph for `c`, in
  // fontconfig's order (language `language` preferred, may be empty);
  // nullptr when none. Faces already
  // handed out are tried first. Variations are applied where the face has
  // the axes. Remembered per (c, language, variations). Faces that cannot be
  // opened are skipped, not thrown.
  std::shared_ptr<const Font> fallback(char32_t c, const std::string& language,
                                       const std::vector<Variation>& variations = {});
  // The same among colour faces only (fontconfig's color, and COLR layers or
  // bitmaps): for emoji presentation sequences, as Pango does. nullptr when
  // none has `c`. Remembered per (c, language).
  std::shared_ptr<const Font> color_fallback(char32_t c, const std::string& language);

  // font.glyph_for_codepoint(c) != 0, remembered per face for the Basic
  // Multilingual Plane (two 8 KiB bit sets per face, filled as characters
  // are asked for): choosing a font per character is then a bit test, not a
  // cmap lookup. `font` must outlive the collection's use of it (faces handed
  // out by the collection do).
  bool has_glyph(const Font& font, char32_t c);

  // Counts since construction.
  struct Stats {
    std::size_t fontconfig_queries = 0;
    std::size_t fallback_hits = 0;  // answered from the cache
    std::size_t faces = 0;          // faces opened
  };
  Stats stats() const { return stats_; }

 private:
  // Where fontconfig's match for a pattern lies, and the style it asked for
  // (OpenType weight, 0: none; italic or oblique). index -1: no face of the
  // family the pattern was checked against.
  struct Match {
    std::string file;
    int index = -1;
    double weight = 0.0;
    bool slanted = false;
  };
  std::shared_ptr<const Font> open_file(const std::string& path, int index, const std::vector<Variation>& variations,
                                        bool strict, const FontSynthesis& synthesis = {});
  std::shared_ptr<const Font> resolve_styled_file(const std::string& file, const std::string& style,
                                                  const std::vector<Variation>& variations);
  std::shared_ptr<const Font> find_fallback(char32_t c, const std::string& language,
                                            const std::vector<Variation>& variations, bool color_only);
  std::string default_path_;
  std::map<std::string, std::shared_ptr<const Font>> by_key_;    // path#index|variations -> face
  std::map<std::string, Match> by_pattern_;                      // fontconfig pattern -> match
  std::map<std::string, std::shared_ptr<const Font>> fallback_;  // codepoint|lang|variations -> face or null
  std::vector<std::shared_ptr<const Font>> fallback_faces_;      // order of first use
  struct Coverage {
    std::vector<std::uint64_t> known, has;  // BMP bit sets
  };
  std::unordered_map<const Font*, Coverage> coverage_;
  const Font* last_font_ = nullptr;
  Coverage* last_coverage_ = nullptr;
  Stats stats_;
};

// True when the face has outlines curvetext can draw (glyf, CFF or CFF2);
// false for a colour bitmap face (Font::color_format() says Bitmap).
// Reads the face's table directory; thread-safe as Font's const functions.
CURVETEXT_API bool has_outlines(const Font& font);

}  // namespace curvetext
