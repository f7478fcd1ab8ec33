// The CLI's option values (tools/curvetext/option_values.hpp): what each
// option accepts and the errors it gives. The CLI's own behaviour is
// tests/cli/cli_test.sh.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/tolerances.hpp"
#include "option_values.hpp"

namespace curvetext::cli {
namespace {

TEST(CliOptions, AntialiasingAndCurveModes) {
  EXPECT_EQ(parse_antialiasing("none"), AntiAliasing::None);
  EXPECT_EQ(parse_antialiasing("curves"), AntiAliasing::Curves);
  EXPECT_EQ(parse_antialiasing("full"), AntiAliasing::Full);
  EXPECT_EQ(parse_antialiasing("vbaa"), AntiAliasing::Vbaa);
  EXPECT_EQ(parse_antialiasing("msaa"), AntiAliasing::Msaa);
  EXPECT_EQ(parse_antialiasing("auto"), AntiAliasing::Auto);
  EXPECT_EQ(parse_curve_mode("exact"), CurveMode::Exact);
  EXPECT_EQ(parse_curve_mode("paper"), CurveMode::Paper);
  for (const char* bad : {"", "Full", "ssaa", "vbaa2"}) {
    try {
      parse_antialiasing(bad);
      FAIL() << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
    }
  }
  try {
    parse_curve_mode("loop-blinn");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
  }
}

TEST(CliOptions, BlendingFilterAndGamma) {
  EXPECT_EQ(parse_blending("linear"), Blending::Linear);
  EXPECT_EQ(parse_blending("srgb"), Blending::Srgb);
  EXPECT_THROW(parse_blending("gamma"), Error);
  EXPECT_EQ(parse_vbaa_filter("box"), 0.0f);
  EXPECT_EQ(parse_vbaa_filter("paper"), tolerance::kVbaaPaperRing);
  EXPECT_EQ(parse_vbaa_filter("0.25"), 0.25f);
  EXPECT_THROW(parse_vbaa_filter("nan"), Error);
  EXPECT_THROW(parse_vbaa_filter("1.5"), Error);
  EXPECT_NO_THROW(check_gamma(1.8, "--gamma"));
  EXPECT_THROW(check_gamma(std::nan(""), "--gamma"), Error);
  EXPECT_THROW(check_gamma(0.0, "--gamma"), Error);
  try {
    check_gamma(100.0, "--gamma");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
    EXPECT_EQ(std::string(e.what()).rfind("--gamma must be a number from 0.25 to 4", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace curvetext::cli
