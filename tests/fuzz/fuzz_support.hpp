// Shared by the fuzz targets (tests/fuzz/README.md): reading parameters from
// the front of an input, and the checks every mesh must pass. A target
// catches curvetext::Error only (bad input must end in one); anything else,
// a crash, a sanitizer report or a failed check is a finding.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "curvetext/curves.hpp"
#include "curvetext/draw_batch.hpp"
#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/outline.hpp"

namespace curvetext::fuzz {

// Values from the front of the input, consumed in order; past its end every
// read gives 0, so every input decodes to something.
class Input {
 public:
  Input(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  bool empty() const { return pos_ >= size_; }
  std::uint8_t byte() { return empty() ? 0 : data_[pos_++]; }
  std::int16_t int16() {
    const unsigned low = byte();  // its own statement: the bytes are read in order
    return static_cast<std::int16_t>(low | (unsigned{byte()} << 8));
  }
  // Eight bytes as they are: NaN, infinities and subnormals included.
  double raw_double() {
    unsigned char bytes[sizeof(double)] = {};
    for (unsigned char& b : bytes) b = byte();
    double d;
    std::memcpy(&d, bytes, sizeof d);
    return d;
  }
  // A number of any magnitude, mostly ones that make geometry meet: small
  // integers (coincident points), sixteenths, a 16-bit mantissa scaled by any
  // power of two from 2^-1074 (subnormal) to 2^1016, or raw bits.
  double number() {
    switch (byte() % 4) {
      case 0:
        return static_cast<std::int8_t>(byte());
      case 1:
        return int16() / 16.0;
      case 2: {
        const int mantissa = int16();
        return std::ldexp(mantissa, static_cast<std::int8_t>(byte()) * 8 - 50);
      }
      default:
        return raw_double();
    }
  }
  // What is left, as text.
  std::string_view rest() {
    const std::string_view r(reinterpret_cast<const char*>(data_) + pos_, empty() ? 0 : size_ - pos_);
    pos_ = size_;
    return r;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// Reports a failed check (with the fuzzer's input saved by libFuzzer, or the
// replayed file named by the replay driver) and aborts.
[[noreturn]] inline void fail(const std::string& what) {
  std::fprintf(stderr, "fuzz check failed: %s\n", what.c_str());
  std::abort();
}

// The mesh's own invariants: indices in range, finite points, positive finite
// weights; and, when `full`, check_mesh's (area identity, watertight, hull
// separation) against the quadratic outline it was built from.
inline void check_built_mesh(const Mesh& mesh, const Outline& outline, double cubic_tolerance, bool full) {
  const std::size_t n = mesh.points.size();
  for (const Vec2& p : mesh.points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail("mesh point not finite");
  for (const auto& t : mesh.triangles)
    if (t[0] >= n || t[1] >= n || t[2] >= n) fail("triangle index out of range");
  for (const CurvedTriangle& c : mesh.curves) {
    if (c.p0 >= n || c.control >= n || c.p2 >= n) fail("curved triangle index out of range");
    if (!(c.weight > 0) || !std::isfinite(c.weight)) fail("curved triangle weight not positive and finite");
  }
  for (const auto& l : mesh.boundary_lines)
    if (l[0] >= n || l[1] >= n) fail("boundary line index out of range");
  (void)gpu_bytes(mesh);
  if (!full) return;
  const MeshCheck check = check_mesh(mesh, to_quadratic_outline(outline, cubic_tolerance));
  if (!check.ok()) fail("check_mesh: " + check.problems.front());
}

// When set, every mesh the targets build (or the refusal's message) goes to
// it instead of the checks: tests/mesh_hash_test.cpp hashes them.
inline void (*mesh_observer)(const Mesh* mesh, const char* error) = nullptr;

// Builds the mesh of `outline` as a caller would and checks it. A refusal
// (curvetext::Error) is a fine outcome.
inline void mesh_and_check(const Outline& outline, double cubic_tolerance, bool full) {
  Mesh mesh;
  try {
    MeshOptions options;
    options.cubic_tolerance = cubic_tolerance;
    mesh = build_mesh(outline, options);
  } catch (const Error& e) {
    if (mesh_observer) mesh_observer(nullptr, e.what());
    return;
  }
  if (mesh_observer) return mesh_observer(&mesh, nullptr);
  check_built_mesh(mesh, outline, cubic_tolerance, full);
}

}  // namespace curvetext::fuzz
