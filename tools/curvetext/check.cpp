// curvetext check: builds every glyph's mesh and verifies the invariants of
// docs/design.md section 4, so a user can see whether curvetext draws a font right.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cli.hpp"
#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/lod.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/renderer.hpp"

namespace curvetext::cli {

namespace {

struct GlyphFailure {
  unsigned glyph = 0;
  std::vector<std::string> reasons;
};

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

}  // namespace

int run_check(const std::vector<std::string>& arguments) {
  FontChoice font_choice;
  double size_px = 64.0;
  bool json = false;
  long max_glyphs = -1;
  Args args(arguments);
  while (args.next()) {
    const std::string& a = args.option();
    if (font_choice.parse(args)) continue;
    if (a == "--size")
      size_px = parse_number(a, args.value());
    else if (a == "--json")
      json = true;
    else if (a == "--max-glyphs")
      max_glyphs = parse_int(a, args.value());
    else
      throw UsageError{"unknown option " + a};
  }
  if (!(size_px > 0) || !std::isfinite(size_px)) throw Error(ErrorCode::InvalidArgument, "--size must be positive");

  const Font font = font_choice.open();
  const double upem = font.metrics().units_per_em;
  // Cubics are approximated for the level of detail that --size is drawn at.
  const double tolerance = cubic_tolerance_for_lod(lod_for_scale(size_px / upem, upem), upem);
  unsigned count = font.glyph_count();
  if (max_glyphs >= 0) count = std::min<unsigned>(count, static_cast<unsigned>(max_glyphs));

  std::vector<GlyphFailure> failures;
  std::vector<double> build_us;
  build_us.reserve(count);
  double max_area_error = 0, triangles = 0, curved = 0, bytes = 0;
  unsigned empty = 0;
  for (unsigned g = 0; g < count; ++g) {
    GlyphFailure failure{g, {}};
    try {
      const Outline outline = font.glyph_outline(g);
      if (outline.empty()) {
        ++empty;
        continue;
      }
      const auto t0 = std::chrono::steady_clock::now();
      const Mesh mesh = build_mesh(outline, {tolerance});
      const auto t1 = std::chrono::steady_clock::now();
      const double us = std::chrono::duration<double, std::micro>(t1 - t0).count();
      build_us.push_back(us);
      const MeshCheck check = check_mesh(mesh, to_quadratic_outline(outline, tolerance));
      max_area_error = std::max(max_area_error, check.area_rel_error);
      triangles += static_cast<double>(mesh.triangles.size());
      curved += static_cast<double>(mesh.curves.size());
      bytes += static_cast<double>(gpu_bytes(mesh));
      failure.reasons = check.problems;
      if (us > 1e6) failure.reasons.push_back("took " + std::to_string(us / 1e6) + " s (limit 1 s)");
    } catch (const Error& e) {
      failure.reasons.push_back(e.what());
    }
    if (!failure.reasons.empty()) failures.push_back(std::move(failure));
  }

  const double built = std::max<double>(1.0, static_cast<double>(build_us.size()));
  double median_us = 0;
  if (!build_us.empty()) {
    std::nth_element(build_us.begin(), build_us.begin() + static_cast<long>(build_us.size() / 2), build_us.end());
    median_us = build_us[build_us.size() / 2];
  }
  if (json) {
    std::printf("{\"font\": %s, \"face_index\": %d, \"glyphs\": %u, \"empty\": %u, \"failed\": %zu, \"failures\": [",
                json_string(font.path()).c_str(), font.face_index(), count, empty, failures.size());
    for (std::size_t i = 0; i < failures.size(); ++i) {
      std::printf("%s{\"glyph\": %u, \"reasons\": [", i ? ", " : "", failures[i].glyph);
      for (std::size_t k = 0; k < failures[i].reasons.size(); ++k)
        std::printf("%s%s", k ? ", " : "", json_string(failures[i].reasons[k]).c_str());
      std::printf("]}");
    }
    std::printf(
        "], \"max_area_rel_error\": %.3g, \"mean_triangles\": %.2f, \"mean_curved_triangles\": %.2f, "
        "\"mean_bytes\": %.0f, \"build_us_median\": %.2f, \"size_px\": %g}\n",
        max_area_error, (triangles + curved) / built, curved / built, bytes / built, median_us, size_px);
  } else {
    std::printf("font: %s (face %d)\n", font.path().c_str(), font.face_index());
    std::printf("glyphs: %u (%u without contours)\n", count, empty);
    std::printf("failed: %zu\n", failures.size());
    for (const GlyphFailure& f : failures)
      for (const std::string& r : f.reasons) std::printf("  glyph %u: %s\n", f.glyph, r.c_str());
    std::printf("largest relative area error: %.3g\n", max_area_error);
    std::printf("mean triangles per glyph: %.1f (%.1f interior, %.1f curved)\n", (triangles + curved) / built,
                triangles / built, curved / built);
    std::printf("mean GPU bytes per glyph: %.0f\n", bytes / built);
    std::printf("median build time per glyph: %.1f us\n", median_us);
  }
  return failures.empty() ? 0 : 1;
}

}  // namespace curvetext::cli
