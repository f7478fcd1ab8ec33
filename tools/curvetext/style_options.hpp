// Options shared by `render` (single lines and paragraphs) and `shape`: how
// the image is drawn (ImageStyle, image_style.hpp).
#pragma once

#include <string>
#include <vector>

#include "cli.hpp"
#include "curvetext/image_style.hpp"

namespace curvetext::cli {

// --aa, --curve, --bg, --blend, --gamma, --debug, --vbaa-filter and the
// transforms --rotate DEG, --scale SX[,SY], --skew AX[,AY], --perspective
// DEG[,DIST], --transform a,b,c,d,e,f[,g,h,i] (each applied after those
// before it, about the image centre). `shape` has its own --scale (pixels per
// unit), so there the transform's scale is --transform only.
struct StyleCli {
  explicit StyleCli(bool scale_is_transform) : scale_is_transform_(scale_is_transform) {}
  // True when `args.option()` was one of the options above (consumed).
  bool parse(Args& args, ImageStyle& style);
  // The transform given, with --perspective DEG's default distance (twice
  // the larger side of the untransformed width x height image).
  Transform transform(double width, double height) const;
  bool perspective_pending() const { return perspective_pending_; }
  // The first option given that only applies to drawing pixels (every one
  // above but --bg); empty when none. Vector output refuses them by name.
  const std::string& raster_option() const { return raster_option_; }

 private:
  bool parse_transform(Args& args);
  bool parse_drawing(Args& args, ImageStyle& style);
  bool scale_is_transform_;
  Transform transform_;
  bool perspective_pending_ = false;
  double perspective_degrees_ = 0.0;
  std::string raster_option_;
};

std::vector<double> parse_numbers(const std::string& option, const std::string& text, std::size_t lo, std::size_t hi);

}  // namespace curvetext::cli
