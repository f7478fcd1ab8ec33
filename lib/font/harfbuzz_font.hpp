// Private to font/ (and the tests, which shape and measure with HarfBuzz as
// an independent reference): the HarfBuzz font a Font shapes with, and owning
// handles for HarfBuzz objects. The stages after font/ use font/shaper.hpp and
// font/face_queries.hpp instead.
#pragma once

#include <hb.h>

#include <memory>

#include "curvetext/font.hpp"

namespace curvetext {

namespace detail {

struct HbBlobDeleter {
  void operator()(hb_blob_t* blob) const noexcept { hb_blob_destroy(blob); }
};
struct HbFaceDeleter {
  void operator()(hb_face_t* face) const noexcept { hb_face_destroy(face); }
};
struct HbFontDeleter {
  void operator()(hb_font_t* font) const noexcept { hb_font_destroy(font); }
};
struct HbBufferDeleter {
  void operator()(hb_buffer_t* buffer) const noexcept { hb_buffer_destroy(buffer); }
};

using HbBlobPtr = std::unique_ptr<hb_blob_t, HbBlobDeleter>;
using HbFacePtr = std::unique_ptr<hb_face_t, HbFaceDeleter>;
using HbFontPtr = std::unique_ptr<hb_font_t, HbFontDeleter>;
using HbBufferPtr = std::unique_ptr<hb_buffer_t, HbBufferDeleter>;

}  // namespace detail

// The HarfBuzz font of `font` (scale: units per em, at the font's current
// variations). Owned by `font`: valid while it lives (take a reference with
// hb_font_reference to keep it longer). HarfBuzz allows reads from several
// threads at once; nothing may change it while set_variations or
// set_synthesis runs. For a synthesised font (Font::synthesis) its advances
// and glyph extents include the synthesis; the slant of glyph offsets does
// not: a shaped glyph's x_offset gains synthesis().slant * y_offset.
hb_font_t* harfbuzz_font(const Font& font);

}  // namespace curvetext
