// Private interface of shapes/ (the SVG reader's parts): transforms, lengths,
// and the cascade of presentation attributes, style sheets and style
// attributes into each element's computed properties.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/geometry.hpp"
#include "svg_css.hpp"
#include "svg_xml.hpp"

namespace curvetext::svg {

// x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  // This after `o`: (this * o)(p) = this(o(p)).
  Affine operator*(const Affine& o) const {
    return {a * o.a + c * o.b, b * o.a + d * o.b,     a * o.c + c * o.d,
            b * o.c + d * o.d, a * o.e + c * o.f + e, b * o.e + d * o.f + f};
  }
  double determinant() const { return a * d - b * c; }
  Affine inverse() const {
    const double k = 1.0 / determinant();
    return {d * k, -b * k, -c * k, a * k, (c * f - d * e) * k, (b * e - a * f) * k};
  }
  static Affine translate(double x, double y) { return {1, 0, 0, 1, x, y}; }
  static Affine scale(double x, double y) { return {x, 0, 0, y, 0, 0}; }
};

// The `transform` attribute's list. Throws Error(InvalidArgument) with
// `where` for anything else.
Affine parse_transform(std::string_view text, const std::string& where);

// The viewport a length's percentages refer to.
struct Viewport {
  double width = 100.0, height = 100.0;
};
enum class Axis { X, Y, Other };

// A length: a number with px, pt, pc, mm, cm, in, em, ex or % (of the
// viewport along `axis`). nullopt for anything else.
std::optional<double> parse_length(std::string_view text, Axis axis, const Viewport& viewport);

// viewBox + preserveAspectRatio: the map from the box to a viewport of
// width x height at (x, y). Throws for a malformed preserveAspectRatio.
Affine view_box_transform(const std::array<double, 4>& box, std::string_view aspect, double x, double y, double width,
                          double height, const std::string& where);
// "min-x min-y width height"; nullopt when absent, throws when malformed or
// not positive.
std::optional<std::array<double, 4>> parse_view_box(const XmlElement& e);

// The properties the reader knows, inherited ones first.
enum Prop : int {
  kFill,
  kFillRule,
  kFillOpacity,
  kStroke,
  kStrokeWidth,
  kStrokeLinecap,
  kStrokeLinejoin,
  kStrokeMiterlimit,
  kStrokeDasharray,
  kStrokeDashoffset,
  kStrokeOpacity,
  kColor,
  kVisibility,
  kClipRule,
  kMarkerStart,
  kMarkerMid,
  kMarkerEnd,
  kPaintOrder,
  kFirstNotInherited,
  kOpacity = kFirstNotInherited,
  kDisplay,
  kClipPath,
  kMask,
  kFilter,
  kStopColor,
  kStopOpacity,
  kVectorEffect,
  kMixBlendMode,
  kTransformProperty,
  kOverflow,
  kPropCount
};

const char* prop_name(int prop);

// Specified values of one element after the cascade (unset: not specified).
using Specified = std::array<std::optional<std::string>, kPropCount>;
// Computed values: every property set.
using Computed = std::array<std::string, kPropCount>;

// The initial values, with `color` as given.
Computed initial_style(const std::string& color);
// Inheritance: the parent's inherited values, the element's specified ones
// over them ("inherit" takes the parent's).
Computed compute(const Computed& parent, const Specified& own);

// Every element's specified values: presentation attributes, then the
// rules of every <style> sheet by importance, specificity and order, then
// the style attribute. Throws for unsupported sheets (svg_css.hpp) and for
// documents whose elements times rules would take too long to match.
std::vector<Specified> cascade(const XmlDocument& doc);

}  // namespace curvetext::svg
