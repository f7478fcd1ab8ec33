// Font faces: FreeType for outlines, HarfBuzz for metrics and shaping, both
// reading one in-memory copy of the file.

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_MODULE_H
#include FT_MULTIPLE_MASTERS_H
#include FT_OUTLINE_H
#include FT_DRIVER_H

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <system_error>

#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"
#include "font/face_queries.hpp"
#include "font/font_impl.hpp"
#include "font/option_lists.hpp"
#include "font/synthesis.hpp"

namespace curvetext {

namespace {

using detail::AxisInfo;
using detail::FontBytes;

std::string ft_error_text(FT_Error error) {
  // Debian's FreeType is built without FT_CONFIG_OPTION_ERROR_STRINGS, so
  // FT_Error_String usually returns null; the number is still useful.
  const char* text = FT_Error_String(error);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "FreeType error 0x%02x", static_cast<unsigned>(error));
  return text ? std::string(text) + " (" + buffer + ")" : std::string(buffer);
}

FontBytes read_file(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw Error(ErrorCode::FontNotFound, "font file not found: " + path);
  if (!std::filesystem::is_regular_file(status))
    throw Error(ErrorCode::FontNotFound, "font path is not a regular file: " + path);

  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorCode::FontNotFound, "cannot open font file: " + path);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw Error(ErrorCode::FontNotFound, "cannot read font file: " + path);
  // hb_blob_create takes an unsigned int length and FreeType an FT_Long.
  if (static_cast<unsigned long long>(size) > std::numeric_limits<unsigned int>::max())
    throw Error(ErrorCode::FontInvalid, "font file is too large (over 4 GiB): " + path);
  in.seekg(0, std::ios::beg);
  auto bytes = std::make_shared<std::vector<unsigned char>>(static_cast<std::size_t>(size));
  if (size > 0 && !in.read(reinterpret_cast<char*>(bytes->data()), static_cast<std::streamsize>(size)))
    throw Error(ErrorCode::FontNotFound, "cannot read font file: " + path);
  if (bytes->empty()) throw Error(ErrorCode::FontInvalid, "font file is empty: " + path);
  return bytes;
}

detail::FtLibraryPtr new_library() {
  FT_Library library = nullptr;
  if (FT_Error error = FT_Init_FreeType(&library))
    throw Error(ErrorCode::FontInvalid, "cannot initialise FreeType: " + ft_error_text(error));
  detail::FtLibraryPtr owner(library);
  // CFF stem darkening only applies to hinted output, and it is off by
  // default since FreeType 2.8; turn it off explicitly so no build option can
  // make our outlines heavier than the font's. Failure (no CFF module) is fine.
  FT_Bool no_darkening = 1;
  FT_Property_Set(library, "cff", "no-stem-darkening", &no_darkening);
  return owner;
}

// Number of faces, or throws FontInvalid. face_index -1 asks FreeType only
// whether the format is known and how many faces the file holds.
long count_faces(FT_Library library, const FontBytes& bytes, const std::string& path) {
  FT_Face face = nullptr;
  FT_Error error = FT_New_Memory_Face(library, bytes->data(), static_cast<FT_Long>(bytes->size()), -1, &face);
  if (error)
    throw Error(ErrorCode::FontInvalid, "not a font file FreeType can read (" + ft_error_text(error) + "): " + path);
  detail::FtFacePtr owner(face);
  return face->num_faces;
}

std::string tag_to_string(hb_tag_t tag) {
  char text[4];
  hb_tag_to_string(tag, text);
  return std::string(text, 4);
}

// A 1-4 character printable ASCII tag, padded with spaces to four as
// OpenType does; nullopt-like empty string when invalid.
std::string normalise_tag(std::string_view tag) {
  if (tag.empty() || tag.size() > 4) return {};
  for (char c : tag)
    if (c < 0x20 || c > 0x7e) return {};
  std::string padded(tag);
  padded.resize(4, ' ');
  return padded;
}

using detail::trim;

bool has_table(hb_face_t* face, hb_tag_t tag) {
  const detail::HbBlobPtr blob(hb_face_reference_table(face, tag));
  return hb_blob_get_length(blob.get()) > 0;
}

ColorFormat color_format_of(hb_face_t* face) {
  if (has_table(face, HB_TAG('C', 'O', 'L', 'R'))) return ColorFormat::Layers;
  if (has_table(face, HB_TAG('C', 'B', 'D', 'T')) || has_table(face, HB_TAG('s', 'b', 'i', 'x')))
    return ColorFormat::Bitmap;
  return ColorFormat::None;
}

// FNV-1a, 64 bit: stable across runs (the key may be stored) and good enough
// to tell faces and variation settings apart.
struct Fnv1a {
  std::uint64_t value = 0xcbf29ce484222325ull;
  void add(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
      value ^= p[i];
      value *= 0x100000001b3ull;
    }
  }
  template <typename T>
  void add_value(T v) {
    add(&v, sizeof v);
  }
};

void update_cache_key(FontAccess::Impl& impl) {
  Fnv1a hash;
  hash.add(impl.path.data(), impl.path.size());
  hash.add_value<std::uint64_t>(impl.path.size());  // separates path from index
  hash.add_value<std::uint64_t>(impl.bytes_hash);
  hash.add_value<std::int64_t>(impl.face_index);
  // The full clamped coordinate vector, not the caller's list: {} and
  // {wght=default} draw the same outlines and share cache entries, and so do
  // values clamped to the same axis end.
  for (FT_Fixed c : impl.coordinates) hash.add_value<std::int64_t>(c);
  // A synthesised face draws other outlines than the plain one; a plain
  // face hashes nothing more.
  if (impl.synthetic_strength != 0.0 || impl.synthesis.slant != 0.0) {
    hash.add_value<double>(impl.synthetic_strength);
    hash.add_value<double>(impl.synthesis.slant);
  }
  impl.cache_key = hash.value;
}

// Sets the FreeType size at which one font unit is exactly one pixel, i.e. 64
// units of 26.6 (see glyph_outline for why we do not use FT_LOAD_NO_SCALE).
void set_unit_scale(const FontAccess::Impl& impl) {
  const FT_F26Dot6 height = static_cast<FT_F26Dot6>(impl.units_per_em) * 64;
  if (FT_Error error = FT_Set_Char_Size(impl.ft_face, 0, height, 72, 72))
    throw Error(ErrorCode::FontInvalid, "cannot set the font's scale (" + ft_error_text(error) + "): " + impl.path);
}

// FT_Outline_Decompose callbacks. Coordinates come in 26.6 at the unit scale;
// `scale_x/y` turn them back into font units (exactly 1/64 in practice).
struct DecomposeState {
  Outline* outline;
  double scale_x;
  double scale_y;
  Vec2 pen;
  Vec2 to_units(const FT_Vector* v) const {
    return {static_cast<double>(v->x) * scale_x, static_cast<double>(v->y) * scale_y};
  }
};

int decompose_move_to(const FT_Vector* to, void* user) {
  auto* s = static_cast<DecomposeState*>(user);
  s->pen = s->to_units(to);
  s->outline->move_to(s->pen);
  return 0;
}

int decompose_line_to(const FT_Vector* to, void* user) {
  auto* s = static_cast<DecomposeState*>(user);
  s->pen = s->to_units(to);
  s->outline->line_to(s->pen);
  return 0;
}

int decompose_conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
  auto* s = static_cast<DecomposeState*>(user);
  const Vec2 c = s->to_units(control);
  const Vec2 p = s->to_units(to);
  // A quadratic whose control point sits on an end point traces its chord:
  // emit the line, which is the same set of points and saves the tessellator
  // a degenerate curve.
  if (c == s->pen || c == p)
    s->outline->line_to(p);
  else
    s->outline->conic_to(c, p, 1.0);
  s->pen = p;
  return 0;
}

int decompose_cubic_to(const FT_Vector* control1, const FT_Vector* control2, const FT_Vector* to, void* user) {
  auto* s = static_cast<DecomposeState*>(user);
  const Vec2 c1 = s->to_units(control1);
  const Vec2 c2 = s->to_units(control2);
  const Vec2 p = s->to_units(to);
  if (c1 == s->pen && c2 == p)
    s->outline->line_to(p);  // both handles retracted: a straight line
  else
    s->outline->cubic_to(c1, c2, p);
  s->pen = p;
  return 0;
}

}  // namespace

std::vector<Variation> parse_variations(std::string_view text) {
  std::vector<Variation> result;
  for (const std::string_view item : detail::split_comma_list(text)) {
    // Built by appending: GCC 12 warns falsely (-Wrestrict) on "'" + string.
    std::string quoted(1, '\'');
    quoted.append(item).push_back('\'');
    const std::size_t eq = item.find('=');
    if (item.empty() || eq == std::string_view::npos)
      throw Error(ErrorCode::InvalidArgument,
                  "bad variation " + quoted + " in '" + std::string(text) + "': expected tag=value, e.g. wght=700");
    const std::string tag = normalise_tag(trim(item.substr(0, eq)));
    if (tag.empty())
      throw Error(ErrorCode::InvalidArgument,
                  "bad variation axis tag in " + quoted + ": expected 1-4 ASCII characters");
    const std::string_view number = trim(item.substr(eq + 1));
    double value = 0.0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (number.empty() || ec != std::errc() || end != number.data() + number.size() || !std::isfinite(value))
      throw Error(ErrorCode::InvalidArgument, "bad variation value in " + quoted + ": expected a number");
    result.push_back({tag, static_cast<float>(value)});
  }
  return result;
}

Font::Font(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;
Font::~Font() = default;

int Font::face_count(const std::string& path) {
  const FontBytes bytes = read_file(path);
  const detail::FtLibraryPtr library = new_library();
  const long count = count_faces(library.get(), bytes, path);
  return static_cast<int>(std::min<long>(count, std::numeric_limits<int>::max()));
}

namespace {

// The HarfBuzz face and font over the impl's bytes. The blob holds its own
// reference to the bytes (freed by the destroy callback), so HarfBuzz
// objects that outlive the Font stay valid.
void open_harfbuzz(FontAccess::Impl& impl) {
  auto* blob_bytes = new FontBytes(impl.bytes);
  impl.hb_blob_owner.reset(hb_blob_create(reinterpret_cast<const char*>(impl.bytes->data()),
                                          static_cast<unsigned int>(impl.bytes->size()), HB_MEMORY_MODE_READONLY,
                                          blob_bytes, [](void* user) { delete static_cast<FontBytes*>(user); }));
  impl.hb_face_owner.reset(hb_face_create(impl.hb_blob_owner.get(), static_cast<unsigned int>(impl.face_index)));
  impl.hb_font_owner.reset(hb_font_create(impl.hb_face_owner.get()));
  impl.hb_font = impl.hb_font_owner.get();
  // FreeType accepts formats HarfBuzz does not (WOFF, for one): HarfBuzz then
  // sees an empty face with no glyphs.
  if (hb_face_get_glyph_count(impl.hb_face_owner.get()) == 0)
    throw Error(ErrorCode::FontInvalid,
                "HarfBuzz cannot read face " + std::to_string(impl.face_index) + ": " + impl.path);
}

// The variation axes of a variable face, each at its default.
void read_axes(FontAccess::Impl& impl) {
  FT_MM_Var* mm = nullptr;
  if (FT_Error error = FT_Get_MM_Var(impl.ft_face, &mm))
    throw Error(ErrorCode::FontInvalid, "cannot read variation axes (" + ft_error_text(error) + "): " + impl.path);
  for (FT_UInt i = 0; i < mm->num_axis; ++i) {
    const FT_Var_Axis& a = mm->axis[i];
    AxisInfo axis;
    axis.hb_tag = static_cast<std::uint32_t>(a.tag);
    axis.tag = tag_to_string(axis.hb_tag);
    axis.minimum = a.minimum;
    axis.default_value = a.def;
    axis.maximum = a.maximum;
    impl.axes.push_back(axis);
    impl.coordinates.push_back(a.def);
  }
  FT_Done_MM_Var(impl.library_owner.get(), mm);
}

// The face `face_index` of `bytes`; `path` names it in messages and keys the
// glyph cache with `bytes_hash` (0 for a file).
std::unique_ptr<FontAccess::Impl> open_face(FontBytes bytes, const std::string& path, int face_index,
                                            std::uint64_t bytes_hash = 0) {
  auto impl = std::make_unique<FontAccess::Impl>();
  impl->path = path;
  impl->face_index = face_index;
  impl->bytes = std::move(bytes);
  impl->bytes_hash = bytes_hash;
  impl->library_owner = new_library();

  // Check the index against the count first: FreeType reads the upper 16 bits
  // of face_index as a named-instance number, so a large index would silently
  // open a different face instead of failing.
  const long faces = count_faces(impl->library_owner.get(), impl->bytes, path);
  if (face_index < 0 || face_index >= faces)
    throw Error(ErrorCode::FontInvalid, "face index " + std::to_string(face_index) + " out of range (the file has " +
                                            std::to_string(faces) + " face(s)): " + path);

  FT_Face face = nullptr;
  if (FT_Error error = FT_New_Memory_Face(impl->library_owner.get(), impl->bytes->data(),
                                          static_cast<FT_Long>(impl->bytes->size()), face_index, &face))
    throw Error(ErrorCode::FontInvalid,
                "cannot open face " + std::to_string(face_index) + " (" + ft_error_text(error) + "): " + path);
  impl->face_owner.reset(face);
  impl->ft_face = face;
  // HarfBuzz only reads sfnt containers (TrueType/OpenType/collections); a
  // Type 1 or bitmap font would open in FreeType but shape as nothing.
  if (!FT_IS_SFNT(face))
    throw Error(ErrorCode::FontInvalid, "not a TrueType/OpenType font (HarfBuzz cannot shape it): " + path);
  // Bitmap colour fonts (CBDT, sbix) have no outlines but are drawn from
  // their bitmaps; other bitmap-only fonts have nothing curvetext can draw.
  if (!FT_IS_SCALABLE(face) && !(FT_HAS_COLOR(face) && face->num_fixed_sizes > 0))
    throw Error(ErrorCode::FontInvalid, "font has no scalable outlines nor colour bitmaps: " + path);

  open_harfbuzz(*impl);
  // HarfBuzz's own OpenType implementation (the default for hb_font_create,
  // set explicitly so a build where FreeType is the default does not change
  // results), at a scale of one unit per font unit: positions come out in
  // font units.
  // FreeType leaves units_per_EM at 0 for faces without outlines; head has it.
  impl->units_per_em =
      FT_IS_SCALABLE(face) ? face->units_per_EM : static_cast<int>(hb_face_get_upem(impl->hb_face_owner.get()));
  if (impl->units_per_em < 16 || impl->units_per_em > 16384)
    throw Error(ErrorCode::FontInvalid, "font has " + std::to_string(impl->units_per_em) +
                                            " units per em (OpenType allows 16 to 16384): " + path);
  impl->color_format = color_format_of(impl->hb_face_owner.get());
  hb_ot_font_set_funcs(impl->hb_font);
  hb_font_set_scale(impl->hb_font, impl->units_per_em, impl->units_per_em);

  for (hb_tag_t table : {HB_TAG('C', 'F', 'F', ' '), HB_TAG('C', 'F', 'F', '2')}) {
    const detail::HbBlobPtr blob(hb_face_reference_table(impl->hb_face_owner.get(), table));
    if (hb_blob_get_length(blob.get()) > 0) impl->cff_outlines = true;
  }

  if (FT_HAS_MULTIPLE_MASTERS(face)) read_axes(*impl);
  if (FT_IS_SCALABLE(face)) set_unit_scale(*impl);
  update_cache_key(*impl);
  return impl;
}

}  // namespace

std::vector<Variation> detail::named_instance_variations(const Font& font, int instance) {
  const FontAccess::Impl& im = FontAccess::impl(font);
  std::lock_guard<std::mutex> lock(im.ft_mutex);
  FT_MM_Var* mm = nullptr;
  if (!FT_HAS_MULTIPLE_MASTERS(im.ft_face) || FT_Get_MM_Var(im.ft_face, &mm) != 0)
    throw Error(ErrorCode::FontInvalid,
                "named instance " + std::to_string(instance) + " of a face without variations: " + im.path);
  std::vector<Variation> values;
  if (instance >= 1 && static_cast<FT_UInt>(instance) <= mm->num_namedstyles) {
    const FT_Var_Named_Style& style = mm->namedstyle[instance - 1];
    for (FT_UInt i = 0; i < mm->num_axis; ++i)
      values.push_back({tag_to_string(static_cast<std::uint32_t>(mm->axis[i].tag)),
                        static_cast<float>(static_cast<double>(style.coords[i]) / 65536.0)});
  }
  const FT_UInt count = mm->num_namedstyles;
  FT_Done_MM_Var(im.library_owner.get(), mm);
  if (values.empty())
    throw Error(ErrorCode::FontInvalid, "named instance " + std::to_string(instance) + " out of range (the face has " +
                                            std::to_string(count) + "): " + im.path);
  return values;
}

Font Font::open(const std::string& path, int face_index) { return Font(open_face(read_file(path), path, face_index)); }

Font Font::open_memory(std::span<const std::uint8_t> data, const std::string& name, int face_index) {
  if (data.empty()) throw Error(ErrorCode::FontInvalid, "font data is empty: " + name);
  if (data.size() > static_cast<std::size_t>(std::numeric_limits<unsigned int>::max()))
    throw Error(ErrorCode::FontInvalid, "font data is too large (over 4 GiB): " + name);
  // A hash of the bytes keys the glyph cache, with the name: two buffers
  // named alike stay apart, the same bytes opened twice share glyphs.
  Fnv1a hash;
  hash.add(data.data(), data.size());
  return Font(open_face(std::make_shared<const std::vector<unsigned char>>(data.begin(), data.end()), name, face_index,
                        hash.value));
}

void Font::set_variations(const std::vector<Variation>& variations) {
  Impl& im = *impl_;
  std::vector<FT_Fixed> coordinates;
  for (const AxisInfo& axis : im.axes) coordinates.push_back(axis.default_value);
  std::vector<Variation> applied;

  for (const Variation& v : variations) {
    const std::string tag = normalise_tag(v.tag);
    if (tag.empty())
      throw Error(ErrorCode::InvalidArgument, "bad variation axis tag '" + v.tag + "': expected 1-4 ASCII characters");
    if (!std::isfinite(v.value))
      throw Error(ErrorCode::InvalidArgument, "variation value for axis '" + tag + "' is not finite");
    if (im.axes.empty())
      throw Error(ErrorCode::FontInvalid, "font is not variable, cannot set axis '" + tag + "': " + im.path);
    const auto it = std::find_if(im.axes.begin(), im.axes.end(), [&](const AxisInfo& a) { return a.tag == tag; });
    if (it == im.axes.end())
      throw Error(ErrorCode::FontInvalid, "font has no variation axis '" + tag + "': " + im.path);
    const auto index = static_cast<std::size_t>(it - im.axes.begin());
    // Clamp in double before converting, so huge values cannot overflow.
    const double clamped = std::clamp(static_cast<double>(v.value), static_cast<double>(it->minimum) / 65536.0,
                                      static_cast<double>(it->maximum) / 65536.0);
    coordinates[index] = std::clamp(static_cast<FT_Fixed>(std::lround(clamped * 65536.0)), it->minimum, it->maximum);
    // Later settings of the same axis win, as in HarfBuzz.
    const Variation entry{tag, static_cast<float>(static_cast<double>(coordinates[index]) / 65536.0)};
    const auto same = std::find_if(applied.begin(), applied.end(), [&](const Variation& a) { return a.tag == tag; });
    if (same != applied.end())
      *same = entry;
    else
      applied.push_back(entry);
  }

  if (!im.axes.empty()) {
    std::lock_guard<std::mutex> lock(im.ft_mutex);
    // FreeType applies avar itself to design coordinates, as HarfBuzz does in
    // hb_font_set_variations, so both see the same normalised position.
    if (FT_Error error =
            FT_Set_Var_Design_Coordinates(im.ft_face, static_cast<FT_UInt>(coordinates.size()), coordinates.data()))
      throw Error(ErrorCode::FontInvalid, "cannot set variations (" + ft_error_text(error) + "): " + im.path);
    // Changing the instance may reset size objects (MVAR); re-assert the scale.
    set_unit_scale(im);

    // Every axis, not just the ones given: hb_font_set_variations resets the
    // unspecified ones to their defaults anyway, but being explicit keeps the
    // two libraries visibly in step.
    std::vector<hb_variation_t> hb_variations;
    for (std::size_t i = 0; i < im.axes.size(); ++i)
      hb_variations.push_back({im.axes[i].hb_tag, static_cast<float>(static_cast<double>(coordinates[i]) / 65536.0)});
    hb_font_set_variations(im.hb_font, hb_variations.data(), static_cast<unsigned int>(hb_variations.size()));
    // A sub-font copies its parent's coordinates when made.
    if (im.hb_synthetic_owner)
      im.hb_synthetic_owner = detail::make_synthetic_font(im.hb_font, static_cast<hb_position_t>(im.synthetic_strength),
                                                          im.synthesis.slant);
  }
  im.coordinates = std::move(coordinates);
  im.variations = std::move(applied);
  update_cache_key(im);
}

void Font::set_synthesis(const FontSynthesis& synthesis) {
  Impl& im = *impl_;
  const auto in_range = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
  if (!in_range(synthesis.embolden_em, 0.0, tolerance::kMaxSyntheticEmboldenEm))
    throw Error(ErrorCode::InvalidArgument,
                "synthetic emboldening must be 0 to " + std::to_string(tolerance::kMaxSyntheticEmboldenEm) + " em");
  if (!in_range(synthesis.slant, -tolerance::kMaxSyntheticSlant, tolerance::kMaxSyntheticSlant))
    throw Error(ErrorCode::InvalidArgument, "synthetic slant must be -" +
                                                std::to_string(tolerance::kMaxSyntheticSlant) + " to " +
                                                std::to_string(tolerance::kMaxSyntheticSlant));
  const bool any = synthesis.embolden_em != 0.0 || synthesis.slant != 0.0;
  if (any && im.color_format != ColorFormat::None)
    throw Error(ErrorCode::FontInvalid, "a colour font cannot be made synthetic bold or slanted: " + im.path);
  const double strength = std::round(synthesis.embolden_em * im.units_per_em);
  im.hb_synthetic_owner =
      any ? detail::make_synthetic_font(im.hb_font, static_cast<hb_position_t>(strength), synthesis.slant) : nullptr;
  im.synthesis = synthesis;
  im.synthetic_strength = strength;
  update_cache_key(im);
}

const FontSynthesis& Font::synthesis() const { return impl_->synthesis; }
double Font::synthetic_strength() const { return impl_->synthetic_strength; }

hb_font_t* harfbuzz_font(const Font& font) {
  const FontAccess::Impl& im = FontAccess::impl(font);
  return im.hb_synthetic_owner ? im.hb_synthetic_owner.get() : im.hb_font;
}

const std::vector<Variation>& Font::variations() const { return impl_->variations; }
const std::string& Font::path() const { return impl_->path; }
int Font::face_index() const { return impl_->face_index; }

std::string Font::family_name() const {
  const char* name = impl_->ft_face->family_name;
  return name ? std::string(name) : std::string();
}

std::uint64_t Font::cache_key() const { return impl_->cache_key; }

namespace {

// An OpenType metric of `font` in font units (its scale), or `fallback`
// where the face lacks the table.
double ot_metric(hb_font_t* font, hb_ot_metrics_tag_t tag, double fallback) {
  hb_position_t value = 0;
  return hb_ot_metrics_get_position(font, tag, &value) ? static_cast<double>(value) : fallback;
}

}  // namespace

FontMetrics Font::metrics() const {
  FontMetrics m;
  m.units_per_em = impl_->units_per_em;
  hb_font_extents_t extents{};
  // HarfBuzz applies MVAR at the current variations; FreeType's face fields
  // are the default instance's.
  hb_font_get_h_extents(impl_->hb_font, &extents);
  m.ascender = extents.ascender;
  m.descender = extents.descender;
  m.line_gap = extents.line_gap;
  // Read through the font that draws (a synthesised face's sub-font), as
  // its glyphs are.
  hb_font_t* drawn = harfbuzz_font(*this);
  const double em = m.units_per_em;
  m.underline_position = ot_metric(drawn, HB_OT_METRICS_TAG_UNDERLINE_OFFSET, -0.1 * em);
  m.underline_thickness = ot_metric(drawn, HB_OT_METRICS_TAG_UNDERLINE_SIZE, em * 0.05);
  m.strikeout_position = ot_metric(drawn, HB_OT_METRICS_TAG_STRIKEOUT_OFFSET, 0.3 * em);
  m.strikeout_thickness = ot_metric(drawn, HB_OT_METRICS_TAG_STRIKEOUT_SIZE, em * 0.05);
  return m;
}

unsigned Font::glyph_count() const { return static_cast<unsigned>(impl_->ft_face->num_glyphs); }

std::uint32_t Font::glyph_for_codepoint(char32_t codepoint) const {
  hb_codepoint_t glyph = 0;
  // HarfBuzz's cmap lookup, the one the shaper uses, so the two agree.
  if (!hb_font_get_nominal_glyph(impl_->hb_font, static_cast<hb_codepoint_t>(codepoint), &glyph)) return 0;
  return glyph;
}

// Where outlines come from, and why not FT_LOAD_NO_SCALE.
//
// FreeType 2.12 does apply variations with FT_LOAD_NO_SCALE (gvar and CFF2
// blends; checked on Inter: 'H' stems 64 units at wght=100, 556 at 900), but
// it returns whole font units. Measured against HarfBuzz's float drawing:
//  * TrueType at an intermediate instance: points off by up to 0.5 unit
//    (Inter at wght=437), even when loaded scaled, because FreeType rounds
//    the gvar deltas to whole units;
//  * CFF and CFF2: charstring coordinates are floored to whole units whether
//    scaled or not (our CFF2 test 'period' at x=100.25..200.75 loads as
//    100..200, and the variable test font's stem of 120.5 at wght=500 as 120).
// HarfBuzz (hb_font_get_glyph_shape at a scale of units_per_em) keeps these
// exactly, and its advances (HVAR) are the ones layout uses. So we draw with
// HarfBuzz there, and with FreeType for TrueType outlines at the default
// instance, where both agree exactly (checked glyph by glyph on DejaVu Sans
// and Noto Sans up to HarfBuzz's float precision) and FreeType is what the
// reference rendering uses. FreeType loads at a size where one font unit is
// one pixel (x_scale = 64.0), unhinted, which is exact for TrueType.

namespace {

// hb_draw_funcs callbacks; same degenerate-segment handling as above.
void hb_move_to(hb_draw_funcs_t*, void* user, hb_draw_state_t*, float x, float y, void*) {
  auto* s = static_cast<DecomposeState*>(user);
  s->pen = {x, y};
  s->outline->move_to(s->pen);
}

void hb_line_to(hb_draw_funcs_t*, void* user, hb_draw_state_t*, float x, float y, void*) {
  auto* s = static_cast<DecomposeState*>(user);
  s->pen = {x, y};
  s->outline->line_to(s->pen);
}

void hb_quadratic_to(hb_draw_funcs_t*, void* user, hb_draw_state_t*, float cx, float cy, float x, float y, void*) {
  auto* s = static_cast<DecomposeState*>(user);
  const Vec2 c{cx, cy};
  const Vec2 p{x, y};
  if (c == s->pen || c == p)
    s->outline->line_to(p);
  else
    s->outline->conic_to(c, p, 1.0);
  s->pen = p;
}

void hb_cubic_to(hb_draw_funcs_t*, void* user, hb_draw_state_t*, float c1x, float c1y, float c2x, float c2y, float x,
                 float y, void*) {
  auto* s = static_cast<DecomposeState*>(user);
  const Vec2 c1{c1x, c1y};
  const Vec2 c2{c2x, c2y};
  const Vec2 p{x, y};
  if (c1 == s->pen && c2 == p)
    s->outline->line_to(p);
  else
    s->outline->cubic_to(c1, c2, p);
  s->pen = p;
}

void hb_close_path(hb_draw_funcs_t*, void* user, hb_draw_state_t*, void*) {
  static_cast<DecomposeState*>(user)->outline->close();
}

struct HbDrawFuncsDeleter {
  void operator()(hb_draw_funcs_t* funcs) const noexcept { hb_draw_funcs_destroy(funcs); }
};

// Immutable and shared by all fonts and threads (HarfBuzz allows that once
// hb_draw_funcs_make_immutable has been called).
hb_draw_funcs_t* draw_funcs() {
  static const std::unique_ptr<hb_draw_funcs_t, HbDrawFuncsDeleter> funcs = [] {
    hb_draw_funcs_t* f = hb_draw_funcs_create();
    hb_draw_funcs_set_move_to_func(f, hb_move_to, nullptr, nullptr);
    hb_draw_funcs_set_line_to_func(f, hb_line_to, nullptr, nullptr);
    hb_draw_funcs_set_quadratic_to_func(f, hb_quadratic_to, nullptr, nullptr);
    hb_draw_funcs_set_cubic_to_func(f, hb_cubic_to, nullptr, nullptr);
    hb_draw_funcs_set_close_path_func(f, hb_close_path, nullptr, nullptr);
    hb_draw_funcs_make_immutable(f);
    return std::unique_ptr<hb_draw_funcs_t, HbDrawFuncsDeleter>(f);
  }();
  return funcs.get();
}

}  // namespace

Outline Font::glyph_outline(std::uint32_t glyph_id) const {
  Outline outline;
  glyph_outline(glyph_id, outline);
  return outline;
}

namespace {

// The glyph's outline as the font draws it (no synthesis).
void load_outline(const FontAccess::Impl& im, std::uint32_t glyph_id, Outline& outline) {
  outline.clear();
  if (glyph_id >= static_cast<std::uint32_t>(im.ft_face->num_glyphs))
    throw Error(ErrorCode::FontInvalid, "glyph id " + std::to_string(glyph_id) + " out of range (font has " +
                                            std::to_string(im.ft_face->num_glyphs) + " glyphs): " + im.path);
  if (!FT_IS_SCALABLE(im.ft_face))
    throw Error(ErrorCode::FontInvalid, "glyph " + std::to_string(glyph_id) +
                                            " has no outline: the font's glyphs are colour bitmaps (CBDT/sbix), "
                                            "drawn by TextBlock or DrawBatch::from_color_bitmaps: " +
                                            im.path);
  if (im.outlines_from_harfbuzz()) {
    DecomposeState state{&outline, 1.0, 1.0, Vec2{}};
    hb_font_get_glyph_shape(im.hb_font, glyph_id, draw_funcs(), &state);
    outline.close();
    return;
  }

  std::lock_guard<std::mutex> lock(im.ft_mutex);
  if (FT_Error error = FT_Load_Glyph(im.ft_face, glyph_id, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
    throw Error(ErrorCode::FontInvalid,
                "cannot load glyph " + std::to_string(glyph_id) + " (" + ft_error_text(error) + "): " + im.path);
  const FT_GlyphSlot slot = im.ft_face->glyph;
  if (slot->format != FT_GLYPH_FORMAT_OUTLINE)
    throw Error(ErrorCode::FontInvalid, "glyph " + std::to_string(glyph_id) + " has no outline: " + im.path);

  outline.contours().reserve(static_cast<std::size_t>(std::max<short>(slot->outline.n_contours, 0)));
  const FT_Size_Metrics& size = im.ft_face->size->metrics;
  // A 26.6 coordinate c is c = units * x_scale / 65536, so units = c * 65536 /
  // x_scale; with x_scale = 64 << 16 this is exactly c / 64.
  DecomposeState state{&outline, 65536.0 / static_cast<double>(size.x_scale),
                       65536.0 / static_cast<double>(size.y_scale), Vec2{}};
  FT_Outline_Funcs funcs{};
  funcs.move_to = decompose_move_to;
  funcs.line_to = decompose_line_to;
  funcs.conic_to = decompose_conic_to;
  funcs.cubic_to = decompose_cubic_to;
  funcs.shift = 0;
  funcs.delta = 0;
  if (FT_Error error = FT_Outline_Decompose(&slot->outline, &funcs, &state))
    throw Error(ErrorCode::FontInvalid,
                "cannot decompose glyph " + std::to_string(glyph_id) + " (" + ft_error_text(error) + "): " + im.path);
  outline.close();
}

}  // namespace

void Font::glyph_outline(std::uint32_t glyph_id, Outline& outline) const {
  load_outline(*impl_, glyph_id, outline);
  detail::embolden_outline(outline, impl_->synthetic_strength);
  detail::slant_outline(outline, impl_->synthesis.slant);
}

}  // namespace curvetext
