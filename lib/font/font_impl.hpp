// Private: the state behind curvetext::Font, for font/ itself and for the
// tests' FreeType reference rendering, which reach the FreeType face and the
// HarfBuzz font that read the same bytes through FontAccess.
//
// Ownership: Impl owns one FT_Library (one per Font, so fonts never share
// FreeType state and can be used on different threads), the FT_Face, and one
// reference each to the hb_blob_t / hb_face_t / hb_font_t. The font file's
// bytes are held by a shared_ptr that both FreeType (through Impl) and the
// HarfBuzz blob (through its destroy callback) keep alive, so an hb_font_t
// reference taken with hb_font_reference() stays valid even after the Font is
// gone.
//
// Thread safety: FreeType's glyph slot is mutable state, so every FreeType
// call on ft_face must hold ft_mutex (glyph_outline() does). hb_font is
// immutable between set_variations() calls and may be shaped with from several
// threads.
#pragma once

#include <ft2build.h>
#include FT_FREETYPE_H
#include <hb-ot.h>
#include <hb.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <vector>

#include "curvetext/font.hpp"
#include "font/harfbuzz_font.hpp"

namespace curvetext {

namespace detail {

struct FtLibraryDeleter {
  void operator()(FT_Library library) const noexcept { FT_Done_FreeType(library); }
};
struct FtFaceDeleter {
  void operator()(FT_Face face) const noexcept { FT_Done_Face(face); }
};

// FT_Library and FT_Face are pointer typedefs; unique_ptr over the pointee.
using FtLibraryPtr = std::unique_ptr<std::remove_pointer_t<FT_Library>, FtLibraryDeleter>;
using FtFacePtr = std::unique_ptr<std::remove_pointer_t<FT_Face>, FtFaceDeleter>;

using FontBytes = std::shared_ptr<const std::vector<unsigned char>>;

// One variation axis as FreeType reports it (FT_Var_Axis), values in design
// units (FT_Fixed 16.16).
struct AxisInfo {
  std::string tag;  // four characters
  std::uint32_t hb_tag = 0;
  FT_Fixed minimum = 0;
  FT_Fixed default_value = 0;
  FT_Fixed maximum = 0;
};

}  // namespace detail

struct Font::Impl {
  // Declaration order is destruction order in reverse: the bytes go last,
  // after FreeType and HarfBuzz have let go of them.
  detail::FontBytes bytes;
  detail::FtLibraryPtr library_owner;
  detail::FtFacePtr face_owner;
  detail::HbBlobPtr hb_blob_owner;
  detail::HbFacePtr hb_face_owner;
  detail::HbFontPtr hb_font_owner;

  // Non-owning views of the objects above, for callers that want the raw
  // handles (reference rendering, shaping).
  FT_Face ft_face = nullptr;
  hb_font_t* hb_font = nullptr;

  std::string path;
  int face_index = 0;
  int units_per_em = 0;

  // Empty for fonts without variations.
  std::vector<detail::AxisInfo> axes;
  // Current design coordinates, one per axis (clamped), as given to FreeType.
  std::vector<FT_Fixed> coordinates;
  // What set_variations() was last given, deduplicated and clamped.
  std::vector<Variation> variations;
  // set_synthesis(); strength in font units (rounded, as HarfBuzz's
  // advances are whole units at our scale). hb_synthetic_owner: a sub-font of
  // hb_font that shapes and measures the synthesised face (null without one).
  FontSynthesis synthesis;
  double synthetic_strength = 0.0;
  detail::HbFontPtr hb_synthetic_owner;
  std::uint64_t cache_key = 0;
  std::uint64_t bytes_hash = 0;  // of a font opened from memory (0: from a file)

  // The face's outlines are CFF or CFF2 charstrings (not glyf).
  bool cff_outlines = false;
  // COLR layers, else CBDT/sbix bitmaps (lib/font/color_glyphs.cpp); a face
  // with bitmaps only has no outlines (FT_IS_SCALABLE is false).
  ColorFormat color_format = ColorFormat::None;

  // Where glyph_outline() reads outlines (see the comment there): HarfBuzz's
  // hb_font_get_glyph_shape for CFF/CFF2 faces and for variable fonts away
  // from their default instance, where FreeType 2.12 rounds coordinates to
  // whole font units; FreeType otherwise. A FreeType reference rendering of
  // such glyphs can differ from our outline by up to one font unit.
  bool outlines_from_harfbuzz() const {
    if (cff_outlines) return true;
    for (std::size_t i = 0; i < axes.size(); ++i)
      if (coordinates[i] != axes[i].default_value) return true;
    return false;
  }

  mutable std::mutex ft_mutex;
};

// Reaches a Font's state (a friend of Font): font/ itself and the tests'
// FreeType reference rendering. Other stages use font/shaper.hpp and
// font/face_queries.hpp.
struct FontAccess {
  using Impl = Font::Impl;
  static Impl& impl(const Font& font) { return *font.impl_; }
};

}  // namespace curvetext
