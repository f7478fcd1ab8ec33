// SVG path data (SVG 1.1 section 8.3 / SVG 2 paths): M L H V Q T C S A Z in
// absolute and relative forms, implicit repetition, compact numbers ("1e-3",
// ".5.5", "-1-2") and compact arc flags ("a1 1 0 00 1 1").
// Elliptical arcs become exact rational quadratics: the arc is cut into pieces
// of at most 90 degrees; each piece of the unit circle from a0 to a1 is the
// conic with control (cos m, sin m) / cos(d/2), m the middle angle, d = a1 - a0,
// and weight cos(d/2); the ellipse is the affine image (rotate(phi) *
// scale(rx, ry)) of the circle, and affine maps keep conic weights.
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

#include "check.hpp"
#include "curvetext/error.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/tolerances.hpp"

namespace curvetext {

namespace {

class PathParser {
 public:
  explicit PathParser(std::string_view d) : s_(d) {}

  std::vector<ShapeContour> run() {
    char command = 0;
    skip_separators();
    while (pos_ < s_.size()) {
      const char c = s_[pos_];
      if (is_command(c)) {
        command = c;
        ++pos_;
        if (contours_.empty() && !have_start_ && command != 'M' && command != 'm')
          fail("path data must start with M or m");
        if (command == 'Z' || command == 'z') {
          close_path();
          skip_separators();
          continue;
        }
      } else if (command == 0) {
        fail("path data must start with M or m");
      } else if (command == 'Z' || command == 'z') {
        fail("numbers after Z");
      }
      // One set of arguments per round; a command letter is only needed once
      // for repeated sets. After M/m, repeated pairs are L/l.
      segment(command);
      if (command == 'M') command = 'L';
      if (command == 'm') command = 'l';
      skip_separators();
    }
    finish_subpath();
    return std::move(contours_);
  }

 private:
  std::string_view s_;
  std::size_t pos_ = 0;
  std::vector<ShapeContour> contours_;
  ShapeContour current_;
  Vec2 pen_{}, start_{};
  bool have_start_ = false;
  std::size_t segments_ = 0;
  // Reflection sources for S/s and T/t.
  Vec2 last_cubic_control_{}, last_quad_control_{};
  char last_ = 0;

  [[noreturn]] void fail(const std::string& message) const {
    throw Error(ErrorCode::InvalidArgument, "SVG path data, character " + std::to_string(pos_ + 1) + ": " + message);
  }

  static bool is_command(char c) {
    switch (c) {
      case 'M':
      case 'm':
      case 'L':
      case 'l':
      case 'H':
      case 'h':
      case 'V':
      case 'v':
      case 'C':
      case 'c':
      case 'S':
      case 's':
      case 'Q':
      case 'q':
      case 'T':
      case 't':
      case 'A':
      case 'a':
      case 'Z':
      case 'z':
        return true;
      default:
        return false;
    }
  }

  void skip_separators() {
    while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == ',' || s_[pos_] == '\t' || s_[pos_] == '\n' ||
                                s_[pos_] == '\r' || s_[pos_] == '\f'))
      ++pos_;
  }

  // SVG number: sign? (digits ('.' digits?)? | '.' digits) exponent?
  double number() {
    skip_separators();
    const std::size_t start = pos_;
    auto at = [&](std::size_t i) { return i < s_.size() ? s_[i] : '\0'; };
    auto digit = [](char c) { return c >= '0' && c <= '9'; };
    if (at(pos_) == '+' || at(pos_) == '-') ++pos_;
    bool digits = false;
    while (digit(at(pos_))) {
      ++pos_;
      digits = true;
    }
    if (at(pos_) == '.') {
      ++pos_;
      while (digit(at(pos_))) {
        ++pos_;
        digits = true;
      }
    }
    if (!digits) {
      pos_ = start;
      fail(pos_ < s_.size() ? "expected a number, got '" + std::string(1, s_[pos_]) + "'"
                            : "expected a number, got the end of the path data");
    }
    if ((at(pos_) == 'e' || at(pos_) == 'E') &&
        (digit(at(pos_ + 1)) || ((at(pos_ + 1) == '+' || at(pos_ + 1) == '-') && digit(at(pos_ + 2))))) {
      pos_ += 2;
      while (digit(at(pos_))) ++pos_;
    }
    std::string_view text = s_.substr(start, pos_ - start);
    if (text.front() == '+') text.remove_prefix(1);  // from_chars takes no '+'
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec == std::errc::result_out_of_range) {
      const std::size_t e = text.find_first_of("eE");
      if (e != std::string_view::npos && text.substr(e + 1).starts_with('-')) return 0.0;
      pos_ = start;
      fail("number " + std::string(text) + " is out of range");
    }
    if (ec != std::errc() || ptr != text.data() + text.size()) {
      pos_ = start;
      fail("invalid number");
    }
    if (std::abs(v) > kMaxShapeCoordinate) {
      pos_ = start;
      fail("number " + std::string(text) + " is larger than " + shapes_detail::number_text(kMaxShapeCoordinate));
    }
    return v;
  }

  bool flag() {
    skip_separators();
    if (pos_ < s_.size() && (s_[pos_] == '0' || s_[pos_] == '1')) return s_[pos_++] == '1';
    fail("expected an arc flag (0 or 1)");
  }

  Vec2 point(bool relative) {
    const double x = number();
    const double y = number();
    const Vec2 p = relative ? pen_ + Vec2{x, y} : Vec2{x, y};
    try {
      shapes_detail::check_point(p, "SVG path data");
    } catch (const Error& e) {
      fail(e.what());
    }
    return p;
  }

  // `closed`: ended by Z (a stroke joins its ends) rather than by M or the
  // end of the data (a stroke caps them); a fill closes both.
  void finish_subpath(bool closed = false) {
    current_.closed = closed;
    if (!current_.pieces.empty()) contours_.push_back(std::move(current_));
    current_ = {};
  }

  void close_path() {
    // Z also moves the pen back.
    finish_subpath(true);
    pen_ = start_;
    last_ = 'Z';
  }

  void add(RationalBezier piece) {
    if (++segments_ > tolerance::kMaxSegmentsPerPath)
      fail("more than " + std::to_string(tolerance::kMaxSegmentsPerPath) + " segments in one path");
    current_.pieces.push_back(std::move(piece));
  }

  void segment(char command) {
    const bool rel = command >= 'a' && command <= 'z';
    const char up = static_cast<char>(rel ? command - ('a' - 'A') : command);
    // After Z, a drawing command starts a new subpath at the old start.
    switch (up) {
      case 'M': {
        finish_subpath();
        pen_ = start_ = point(rel);
        have_start_ = true;
        break;
      }
      case 'L': {
        const Vec2 p = point(rel);
        add(RationalBezier::line(pen_, p));
        pen_ = p;
        break;
      }
      case 'H': {
        const double x = number();
        const Vec2 p{rel ? pen_.x + x : x, pen_.y};
        check(p);
        add(RationalBezier::line(pen_, p));
        pen_ = p;
        break;
      }
      case 'V': {
        const double y = number();
        const Vec2 p{pen_.x, rel ? pen_.y + y : y};
        check(p);
        add(RationalBezier::line(pen_, p));
        pen_ = p;
        break;
      }
      case 'C':
      case 'S': {
        Vec2 c1;
        if (up == 'C')
          c1 = point(rel);
        else
          c1 = (last_ == 'C' || last_ == 'S') ? pen_ * 2.0 - last_cubic_control_ : pen_;
        const Vec2 c2 = point(rel);
        const Vec2 p = point(rel);
        add(RationalBezier::cubic(pen_, c1, c2, p));
        last_cubic_control_ = c2;
        pen_ = p;
        break;
      }
      case 'Q':
      case 'T': {
        Vec2 c;
        if (up == 'Q')
          c = point(rel);
        else
          c = (last_ == 'Q' || last_ == 'T') ? pen_ * 2.0 - last_quad_control_ : pen_;
        check(c);
        const Vec2 p = point(rel);
        add(RationalBezier::conic(pen_, c, p, 1.0));
        last_quad_control_ = c;
        pen_ = p;
        break;
      }
      case 'A': {
        const double rx = number(), ry = number(), phi = number();
        const bool large = flag(), sweep = flag();
        const Vec2 p = point(rel);
        arc(rx, ry, phi, large, sweep, p);
        pen_ = p;
        break;
      }
      default:
        fail("unknown command");
    }
    last_ = up;
  }

  void check(Vec2 p) {
    try {
      shapes_detail::check_point(p, "SVG path data");
    } catch (const Error& e) {
      fail(e.what());
    }
  }

  // SVG implementation notes F.6.5 (endpoint to centre parametrisation) and
  // F.6.6 (out-of-range radii are scaled up until the arc exists). Worked in
  // units of the larger radius, so radii from 1e-300 to 1e9 neither
  // overflow nor vanish when squared.
  void arc(double rx, double ry, double phi_degrees, bool large, bool sweep, Vec2 p) {
    const Vec2 p0 = pen_;
    if (p0 == p) return;  // the spec: omit the arc
    rx = std::abs(rx);
    ry = std::abs(ry);
    if (rx == 0.0 || ry == 0.0) {
      add(RationalBezier::line(p0, p));
      return;
    }
    const double phi = std::fmod(phi_degrees, 360.0) * std::numbers::pi / 180.0;
    const double cp = std::cos(phi), sp = std::sin(phi);
    const Vec2 h = (p0 - p) * 0.5;
    const Vec2 q{cp * h.x + sp * h.y, -sp * h.x + cp * h.y};  // (x1', y1')
    // sqrt(lambda) of F.6.6; infinite for radii far too small, which is > 1 too.
    const bool scale_up = std::hypot(q.x / rx, q.y / ry) > 1.0;
    if (scale_up) {
      // rx * sqrt(lambda) and ry * sqrt(lambda) without forming lambda.
      const double aspect = ry / rx;
      rx = std::hypot(q.x, q.y / aspect);
      ry = std::hypot(q.x * aspect, q.y);
    }
    const double r = std::max(rx, ry);
    const double ra = rx / r, rb = ry / r;
    const Vec2 qn = q / r;
    if (!(std::isfinite(r) && ra > 0.0 && rb > 0.0))
      fail("arc radii " + shapes_detail::number_text(rx) + " and " + shapes_detail::number_text(ry) +
           " are too far apart to draw");
    // The centre: the midpoint when the radii were scaled up (lambda = 1).
    double coef = 0.0;
    if (!scale_up) {
      const double num = ra * ra * rb * rb - ra * ra * qn.y * qn.y - rb * rb * qn.x * qn.x;
      const double den = ra * ra * qn.y * qn.y + rb * rb * qn.x * qn.x;
      coef = den > 0.0 ? std::sqrt(std::max(0.0, num / den)) : 0.0;
      if (large == sweep) coef = -coef;
    }
    const Vec2 cq{coef * ra * qn.y / rb, -coef * rb * qn.x / ra};  // in units of r
    const Vec2 mid = (p0 + p) * 0.5;
    const Vec2 centre{(cp * cq.x - sp * cq.y) * r + mid.x, (sp * cq.x + cp * cq.y) * r + mid.y};
    const Vec2 u{(qn.x - cq.x) / ra, (qn.y - cq.y) / rb};
    const Vec2 v{(-qn.x - cq.x) / ra, (-qn.y - cq.y) / rb};
    const double theta1 = std::atan2(u.y, u.x);
    double delta = std::atan2(cross(u, v), dot(u, v));
    if (!sweep && delta > 0) delta -= 2 * std::numbers::pi;
    if (sweep && delta < 0) delta += 2 * std::numbers::pi;
    if (!std::isfinite(theta1) || !std::isfinite(delta) || !std::isfinite(centre.x) || !std::isfinite(centre.y))
      fail("the arc's centre cannot be computed from its radii and end points");
    // At most 90 degrees per conic: w = cos(d/2) >= cos(45 deg), far from 0.
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / (std::numbers::pi / 2) - 1e-9)));
    const double d = delta / n;
    const double w = std::cos(d / 2);
    auto map = [&](Vec2 unit) {  // centre + rotate(phi) * scale(rx, ry) * unit
      const Vec2 e{rx * unit.x, ry * unit.y};
      return Vec2{centre.x + cp * e.x - sp * e.y, centre.y + sp * e.x + cp * e.y};
    };
    Vec2 a = p0;
    for (int k = 0; k < n; ++k) {
      const double a0 = theta1 + k * d, am = a0 + d / 2;
      // The last end is the given end point exactly, so the path stays closed.
      const Vec2 b = k + 1 == n ? p : map({std::cos(a0 + d), std::sin(a0 + d)});
      const Vec2 control = map(Vec2{std::cos(am), std::sin(am)} / w);
      add(RationalBezier::conic(a, control, b, w));
      a = b;
    }
  }
};

}  // namespace

std::vector<ShapeContour> parse_svg_path(std::string_view d) { return PathParser(d).run(); }

}  // namespace curvetext
