// Synthetic bold and slant (see synthesis.hpp and FontSynthesis).

#include "font/synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace curvetext::detail {

namespace {

// Points a segment contributes to its contour's control polygon: its start
// and control points (its end is the next segment's start).
int own_points(const Segment& s) {
  switch (s.kind) {
    case Segment::Kind::Line:
      return 1;
    case Segment::Kind::Conic:
      return 2;
    case Segment::Kind::Cubic:
      return 3;
  }
  return 1;
}

void contour_points(const Contour& contour, std::vector<Vec2>& points) {
  points.clear();
  for (const Segment& s : contour.segments)
    for (int i = 0; i < own_points(s); ++i) points.push_back(s.p[i]);
}

void set_contour_points(Contour& contour, const std::vector<Vec2>& points) {
  std::size_t k = 0;
  for (Segment& s : contour.segments) {
    const int n = own_points(s);
    for (int i = 0; i < n; ++i) s.p[i] = points[k + static_cast<std::size_t>(i)];
    k += static_cast<std::size_t>(n);
    s.p[n] = points[k % points.size()];
  }
}

// FT_Outline_Get_Orientation's sign: the control polygons' doubled signed
// area over all contours; > 0 is counter-clockwise with y up (PostScript).
double control_polygon_area(const Outline& outline, std::vector<Vec2>& points) {
  double area = 0.0;
  for (const Contour& c : outline.contours()) {
    contour_points(c, points);
    for (std::size_t i = 0, j = points.size() - 1; i < points.size(); j = i++)
      area += (points[i].y - points[j].y) * (points[i].x + points[j].x);
  }
  return area;
}

// The shift of the corner between unit edges `in` and `out` (lengths l_in,
// l_out), as FT_Outline_EmboldenXY computes it: along the bisector of the
// normals, at most as long as the shorter edge allows.
Vec2 corner_shift(Vec2 in, Vec2 out, double l_in, double l_out, double half, bool clockwise) {
  double d = dot(in, out);
  if (d <= -0.9375) return {};  // a turn of more than about 160 degrees
  d += 1.0;
  Vec2 shift{in.y + out.y, in.x + out.x};
  double q = out.x * in.y - out.y * in.x;
  if (clockwise) {
    shift.x = -shift.x;
    q = -q;
  } else {
    shift.y = -shift.y;
  }
  const double l = std::min(l_in, l_out);
  const double scale = half * q <= l * d ? half / d : l / q;
  return shift * scale;
}

// One contour's points moved (FT_Outline_EmboldenXY's loop: i trails j and
// moves the points from i up to j once the corner at i is known; k marks the
// first corner, whose incoming edge is kept as `anchor` for the wrap-around).
void embolden_contour(std::vector<Vec2>& p, double half, bool clockwise) {
  const std::size_t n = p.size();
  if (n < 2) return;
  const std::vector<Vec2> original = p;
  const std::size_t none = n;
  Vec2 in{}, out{}, anchor{};
  double l_in = 0.0, l_out = 0.0, l_anchor = 0.0;
  std::size_t i = n - 1, j = 0, k = none;
  for (; j != i && i != k; j = j + 1 < n ? j + 1 : 0) {
    if (j != k) {
      out = original[j] - original[i];
      l_out = length(out);
      if (l_out == 0.0) continue;
      out = out / l_out;
    } else {
      out = anchor;
      l_out = l_anchor;
    }
    if (l_in != 0.0) {
      if (k == none) {
        k = i;
        anchor = in;
        l_anchor = l_in;
      }
      const Vec2 shift = corner_shift(in, out, l_in, l_out, half, clockwise);
      for (; i != j; i = i + 1 < n ? i + 1 : 0) p[i] = original[i] + Vec2{half + shift.x, half + shift.y};
    } else {
      i = j;
    }
    in = out;
    l_in = l_out;
  }
}

struct SyntheticData {
  hb_position_t strength = 0;
  double slant = 0.0;
};

const SyntheticData& data_of(void* font_data) { return *static_cast<const SyntheticData*>(font_data); }

hb_position_t h_advance(hb_font_t* font, void* font_data, hb_codepoint_t glyph, void*) {
  const hb_position_t a = hb_font_get_glyph_h_advance(hb_font_get_parent(font), glyph);
  return a != 0 ? a + data_of(font_data).strength : 0;
}

void h_advances(hb_font_t* font, void* font_data, unsigned count, const hb_codepoint_t* first_glyph,
                unsigned glyph_stride, hb_position_t* first_advance, unsigned advance_stride, void*) {
  hb_font_get_glyph_h_advances(hb_font_get_parent(font), count, first_glyph, glyph_stride, first_advance,
                               advance_stride);
  auto* bytes = reinterpret_cast<unsigned char*>(first_advance);
  for (unsigned i = 0; i < count; ++i) {
    auto* a = reinterpret_cast<hb_position_t*>(bytes + static_cast<std::size_t>(i) * advance_stride);
    if (*a != 0) *a += data_of(font_data).strength;
  }
}

// HarfBuzz's extents: y_bearing is the top, height is negative.
hb_bool_t glyph_extents(hb_font_t* font, void* font_data, hb_codepoint_t glyph, hb_glyph_extents_t* e, void*) {
  if (!hb_font_get_glyph_extents(hb_font_get_parent(font), glyph, e)) return false;
  if (e->width == 0 && e->height == 0) return true;
  const SyntheticData& d = data_of(font_data);
  e->width += d.strength;
  e->y_bearing += d.strength;
  e->height -= d.strength;
  const double top = e->y_bearing, bottom = static_cast<double>(e->y_bearing) + e->height;
  const double x0 = e->x_bearing + std::min(d.slant * top, d.slant * bottom);
  const double x1 = static_cast<double>(e->x_bearing) + e->width + std::max(d.slant * top, d.slant * bottom);
  e->x_bearing = static_cast<hb_position_t>(std::floor(x0));
  e->width = static_cast<hb_position_t>(std::ceil(x1) - std::floor(x0));
  return true;
}

struct HbFontFuncsDeleter {
  void operator()(hb_font_funcs_t* funcs) const noexcept { hb_font_funcs_destroy(funcs); }
};

// Immutable and shared by every synthesised font; the functions not set
// here ask the parent font (HarfBuzz's default for a sub-font).
hb_font_funcs_t* synthetic_funcs() {
  static const std::unique_ptr<hb_font_funcs_t, HbFontFuncsDeleter> funcs = [] {
    hb_font_funcs_t* f = hb_font_funcs_create();
    hb_font_funcs_set_glyph_h_advance_func(f, h_advance, nullptr, nullptr);
    hb_font_funcs_set_glyph_h_advances_func(f, h_advances, nullptr, nullptr);
    hb_font_funcs_set_glyph_extents_func(f, glyph_extents, nullptr, nullptr);
    hb_font_funcs_make_immutable(f);
    return std::unique_ptr<hb_font_funcs_t, HbFontFuncsDeleter>(f);
  }();
  return funcs.get();
}

}  // namespace

void embolden_outline(Outline& outline, double strength) {
  if (strength == 0.0 || outline.empty()) return;
  std::vector<Vec2> points;
  const double area = control_polygon_area(outline, points);
  if (area == 0.0) return;
  for (Contour& c : outline.contours()) {
    if (c.segments.empty()) continue;
    contour_points(c, points);
    embolden_contour(points, strength / 2.0, area < 0.0);
    set_contour_points(c, points);
  }
}

void slant_outline(Outline& outline, double slant) {
  if (slant == 0.0) return;
  for (Contour& c : outline.contours())
    for (Segment& s : c.segments)
      for (int i = 0; i <= own_points(s); ++i) s.p[i].x += slant * s.p[i].y;
}

HbFontPtr make_synthetic_font(hb_font_t* parent, hb_position_t strength, double slant) {
  HbFontPtr font(hb_font_create_sub_font(parent));
  auto* data = new SyntheticData{strength, slant};
  hb_font_set_funcs(font.get(), synthetic_funcs(), data, [](void* d) { delete static_cast<SyntheticData*>(d); });
  return font;
}

}  // namespace curvetext::detail
