// How build_mesh and check_mesh scale with the size of large synthetic
// outlines, the shapes where their work has been superlinear: combs (many
// tall teeth on one long base), a comb crossed by a bar, a polygon circle and
// a path that runs over one square again and again. Prints a Markdown table
// of seconds per call and the growth from the previous size (x4 pieces: 4 for
// linear work, 16 for quadratic), four sizes per shape from n = 250 (256 for
// the square, whose largest path is then 65,536 segments), up to N.
// docs/reliability.md quotes it.
//
//   build/bench/mesh_scaling_bench [--max-teeth N]   (default 16384)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/outline.hpp"

namespace {

using namespace curvetext;

// n teeth of width 4 and heights 1000 + i on a base of height 1, one contour;
// curved: each tooth's top is a parabola.
Outline comb(int n, bool curved) {
  Outline o;
  o.move_to({0, 0});
  for (int i = 0; i < n; ++i) {
    const double x = i * 10.0, h = 1000.0 + i;
    if (curved) {
      o.conic_to({x + 2, h + 5}, {x + 4, h});
    } else {
      o.line_to({x + 2, h});
      o.line_to({x + 4, h});
    }
    o.line_to({x + 4, 1});
    o.line_to({x + 10, 1});
  }
  o.line_to({n * 10.0, 0});
  o.close();
  return o;
}

Outline comb_with_bar(int n) {
  Outline o = comb(n, false);
  o.move_to({-5, 500});
  o.line_to({n * 10.0 + 5, 500});
  o.line_to({n * 10.0 + 5, 501});
  o.line_to({-5, 501});
  o.close();
  return o;
}

Outline circle(int n) {
  Outline o;
  for (int i = 0; i < 4 * n; ++i) {
    const double a = 2.0 * 3.141592653589793 * i / (4 * n);
    const Vec2 p{1000 * std::cos(a), 1000 * std::sin(a)};
    if (i == 0) {
      o.move_to(p);
    } else {
      o.line_to(p);
    }
  }
  o.close();
  return o;
}

Outline retraced(int n) {
  Outline o;
  o.move_to({0, 0});
  for (int i = 0; i < n; ++i) {
    o.line_to({1000, 0});
    o.line_to({1000, 1000});
    o.line_to({0, 1000});
    o.line_to({0, 0});
  }
  o.close();
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Shape {
  const char* name;
  std::function<Outline(int)> make;
  int first_n = 250;
};

}  // namespace

int main(int argc, char** argv) {
  int max_teeth = 16384;
  const char* only = "";  // --shape TEXT: only the shapes whose name contains it
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--max-teeth") == 0) max_teeth = std::atoi(argv[i + 1]);
    if (std::strcmp(argv[i], "--shape") == 0) only = argv[i + 1];
  }
  const std::vector<Shape> shapes = {{"comb of lines", [](int n) { return comb(n, false); }},
                                     {"comb, curved tops", [](int n) { return comb(n, true); }},
                                     {"comb crossed by a bar", comb_with_bar},
                                     {"polygon circle", circle},
                                     {"square run over n times", retraced, 256}};
  std::printf("| Shape | n | Pieces | build_mesh s | growth | check_mesh s | growth | Result |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---|\n");
  for (const Shape& shape : shapes) {
    if (std::strstr(shape.name, only) == nullptr) continue;
    double last_build = 0.0, last_check = 0.0;
    for (int n = shape.first_n, k = 0; k < 4 && n <= max_teeth; ++k, n *= 4) {
      const Outline outline = shape.make(n);
      std::size_t pieces = 0;
      for (const Contour& c : outline.contours()) pieces += c.segments.size();
      std::string result = "ok";
      Mesh mesh;
      auto t0 = std::chrono::steady_clock::now();
      try {
        build_mesh(outline, MeshOptions{}, mesh);
      } catch (const Error& e) {
        result = e.what();
      }
      const double build = seconds_since(t0);
      double check = 0.0;
      if (result == "ok") {
        t0 = std::chrono::steady_clock::now();
        const MeshCheck c = check_mesh(mesh, to_quadratic_outline(outline, MeshOptions{}.cubic_tolerance));
        check = seconds_since(t0);
        if (!c.ok()) result = "check: " + c.problems.front();
      }
      auto growth = [](double now, double before) {
        char buf[32];
        std::snprintf(buf, sizeof buf, before > 0.0 && now > 0.0 ? "%.1f" : "", now / before);
        return std::string(buf);
      };
      std::printf("| %s | %d | %zu | %.3f | %s | %.3f | %s | %s |\n", shape.name, n, pieces, build,
                  growth(build, last_build).c_str(), check, growth(check, last_check).c_str(), result.c_str());
      std::fflush(stdout);
      last_build = build;
      last_check = check;
    }
  }
  return 0;
}
