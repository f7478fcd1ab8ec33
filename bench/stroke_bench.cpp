// Strokes (docs/strokes.md, docs/performance.md "Strokes"): building time per
// segment by join kind, and the zoom of a drawing of 1,000 device-pixel
// strokes, rebuilt every frame against rebuilt when stroke_build_scale's
// bucket changes. CPU only (stroke_outline and build_mesh; drawing a mesh
// costs the same either way). Prints markdown tables.
//
//   build/bench/stroke_bench [--quick]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/stroke.hpp"
#include "curvetext/tolerances.hpp"

namespace {

using namespace curvetext;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// An open polyline of n segments of length 10 heading up to 69 degrees
// either side of +x (corners up to 137 degrees, never crossing itself), or
// the same corners joined by quadratic curves (conics of weight 1: offsets
// fitted) when `curves`.
ShapeContour wander(int n, bool curves, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> turn(-1.2, 1.2);
  ShapeContour c;
  c.closed = false;
  Vec2 p{0, 0};
  double heading = 0.0;
  for (int i = 0; i < n; ++i) {
    heading = turn(rng);
    const Vec2 q = p + Vec2{std::cos(heading), std::sin(heading)} * 10.0;
    if (curves) {
      const Vec2 mid = (p + q) * 0.5 + Vec2{-std::sin(heading), std::cos(heading)} * 3.0;
      c.pieces.push_back(RationalBezier::conic(p, mid, q, 1.0));
    } else {
      c.pieces.push_back(RationalBezier::line(p, q));
    }
    p = q;
  }
  return c;
}

// n parabolic arcs along +x, their control points up and down in turn: a
// smooth wave (no corners; offsets fitted).
ShapeContour wave(int n) {
  ShapeContour c;
  c.closed = false;
  for (int i = 0; i < n; ++i)
    c.pieces.push_back(
        RationalBezier::conic({i * 10.0 - 5, 0}, {i * 10.0, i % 2 ? 4.0 : -4.0}, {i * 10.0 + 5, 0}, 1.0));
  return c;
}

void build_table(int segments, int repeats) {
  std::printf(
      "\n| path (%d segments, width 3, tolerance 1/64) | join | stroke µs/segment | mesh µs/segment | "
      "outline segments |\n| --- | --- | ---: | ---: | ---: |\n",
      segments);
  const char* names[] = {"miter", "miter-clip", "round", "bevel", "arcs"};
  const char* kinds[] = {"lines, corners up to 137 degrees", "quadratic curves, corners up to 137 degrees",
                         "quadratic curves, a smooth wave"};
  for (int kind = 0; kind < 3; ++kind) {
    const std::vector<ShapeContour> path{kind == 2 ? wave(segments) : wander(segments, kind == 1, 7)};
    for (int j = 0; j < 5; ++j) {
      StrokeStyle st;
      st.width = 3.0;
      st.join = static_cast<LineJoin>(j);
      Stroker stroker;
      Outline out;
      double stroke_s = 1e300, mesh_s = 1e300;
      std::size_t count = 0;
      std::string refused;
      for (int r = 0; r < repeats; ++r) {
        out.clear();
        auto t0 = Clock::now();
        stroker.stroke(path, st, tolerance::kStrokeOffsetPx, 1.0, out);
        stroke_s = std::min(stroke_s, seconds_since(t0));
        t0 = Clock::now();
        try {
          const Mesh m = build_mesh(out);
        } catch (const Error& e) {
          refused = e.what();
        }
        mesh_s = std::min(mesh_s, seconds_since(t0));
        count = 0;
        for (const Contour& c : out.contours()) count += c.segments.size();
      }
      char mesh[64];
      std::snprintf(mesh, sizeof mesh, "%.2f", mesh_s / segments * 1e6);
      std::printf("| %s | %s | %.2f | %s | %zu |\n", kinds[kind], names[j], stroke_s / segments * 1e6,
                  refused.empty() ? mesh : "refused", count);
      if (!refused.empty()) std::fprintf(stderr, "%s\n", refused.c_str());
    }
  }
}

// 1,000 paths of 8 segments with 1 px device-pixel strokes, zoomed from 1x
// to 4x by 1% a frame; a frame's CPU cost is the strokes and meshes it
// rebuilds.
void zoom_table(int paths, int frames_every) {
  std::vector<std::vector<ShapeContour>> drawing;
  for (int i = 0; i < paths; ++i) drawing.push_back({wander(8, i % 2 == 1, 100 + i)});
  StrokeStyle st;
  st.width = 1.0;
  st.width_unit = StrokeWidthUnit::Device;
  Stroker stroker;
  Outline out;
  auto rebuild = [&](double scale) {
    for (const auto& path : drawing) {
      out.clear();
      stroker.stroke(path, st, tolerance::kStrokeOffsetPx / scale, scale, out);
      (void)build_mesh(out);
    }
  };
  std::vector<double> scales;
  for (double s = 1.0; s < 4.0; s *= 1.01) scales.push_back(s);
  // Every frame: time a sample of frames (every `frames_every`-th).
  double every_total = 0.0;
  int sampled = 0;
  for (std::size_t f = 0; f < scales.size(); f += frames_every, ++sampled) {
    const auto t0 = Clock::now();
    rebuild(scales[f]);
    every_total += seconds_since(t0);
  }
  const double every_frame = every_total / sampled;
  // Bucketed: rebuild when stroke_build_scale changes.
  double bucket_total = 0.0, worst = 0.0, built = 0.0;
  int rebuilds = 0;
  for (double s : scales) {
    const double b = stroke_build_scale(st, s);
    if (b == built) continue;
    built = b;
    const auto t0 = Clock::now();
    rebuild(b);
    const double t = seconds_since(t0);
    bucket_total += t;
    worst = std::max(worst, t);
    ++rebuilds;
  }
  std::printf(
      "\n| zoom 1x to 4x, %zu frames, %d paths of 8 segments, 1 px device-pixel strokes | ms per frame (mean) | "
      "worst frame ms | frames that rebuild |\n| --- | ---: | ---: | ---: |\n",
      scales.size(), paths);
  std::printf("| rebuilt every frame (%d frames timed) | %.1f | %.1f | %zu |\n", sampled, every_frame * 1e3,
              every_frame * 1e3, scales.size());
  std::printf("| rebuilt when stroke_build_scale changes | %.1f | %.1f | %d |\n",
              bucket_total / static_cast<double>(scales.size()) * 1e3, worst * 1e3, rebuilds);
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  build_table(quick ? 1024 : 4096, quick ? 2 : 5);
  zoom_table(quick ? 200 : 1000, quick ? 40 : 10);
  return 0;
}
