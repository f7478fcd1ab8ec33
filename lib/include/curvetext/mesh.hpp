// Meshes (paper 3.1-3.2): an outline of lines and conics becomes interior
// triangles plus one curved triangle per conic piece. Size independent: the
// mesh is in the outline's units. No GL here; gpu/ packs meshes for drawing.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "curvetext/export.hpp"
#include "curvetext/outline.hpp"

namespace curvetext {

// A curved triangle is the control triangle (p0, control, p2) of one conic
// piece. `convex`: the filled side of the curve is its chord side (the curve
// bulges out of the shape; the interior mesh uses the chord). Otherwise the
// filled side is the outer side (the curve bulges into the shape; the interior
// mesh passes through the control point).
struct CurvedTriangle {
  std::uint32_t p0 = 0;
  std::uint32_t control = 0;
  std::uint32_t p2 = 0;
  double weight = 1.0;
  bool convex = true;
};

struct Mesh {
  // Vertices, shared by index; equal positions use one index so that shared
  // edges are bit-identical.
  std::vector<Vec2> points;
  // Interior triangles, counter-clockwise in a y-up frame.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<CurvedTriangle> curves;
  // Straight pieces of the outline, directed so the filled side is on the left
  // (y-up). Each is an edge of exactly one interior triangle.
  std::vector<std::array<std::uint32_t, 2>> boundary_lines;

  bool empty() const { return triangles.empty() && curves.empty(); }
};

struct MeshOptions {
  // Tolerance for replacing cubics by quadratics, in the outline's units. The
  // caller derives it from the scale the mesh is drawn at (see lod.hpp).
  double cubic_tolerance = 0.25;
  // Which points of the outline the mesh fills. Under EvenOdd every outline
  // goes through crossing resolution (the nonzero path skips it for contours
  // that do not meet).
  FillRule fill_rule = FillRule::NonZero;
};

// Builds the mesh of the nonzero-winding fill of `outline`. Throws
// Error(Geometry) on non-finite input, a cubic_tolerance that is not
// positive and finite, or a coordinate beyond tolerance::kMaxMeshCoordinate;
// coordinates below tolerance::kFlushCoordinate* are read as 0. Never hangs:
// hull separation and crossing resolution have a work budget proportional to
// the input (docs/limits.md), past which they throw
// Error(Geometry), and the other stages are bounded by what those leave. No
// other exception leaves it (running out of memory is Error(Geometry) too).
// A mesh that does not come from the self-checking sweep is checked with
// check_mesh before it is returned; one that fails is Error(Geometry).
// Thread-safe (scratch memory is per thread, or the caller's MeshBuilder).
CURVETEXT_API Mesh build_mesh(const Outline& outline, const MeshOptions& options = {});
// The same into `mesh`, whose contents are replaced and whose storage is
// reused (a glyph cache building many meshes in a row allocates less).
CURVETEXT_API void build_mesh(const Outline& outline, const MeshOptions& options, Mesh& mesh);

// The scratch memory of build_mesh, kept from one mesh to the next (no
// allocation per mesh once warm). build_mesh without a builder uses one of
// its own per thread; a caller that builds meshes on threads of its own, or
// wants the memory back when done, keeps one per thread and passes it. One
// builder serves one build at a time.
class CURVETEXT_API MeshBuilder {
 public:
  MeshBuilder();
  ~MeshBuilder();
  MeshBuilder(MeshBuilder&&) noexcept;
  MeshBuilder& operator=(MeshBuilder&&) noexcept;
  MeshBuilder(const MeshBuilder&) = delete;
  MeshBuilder& operator=(const MeshBuilder&) = delete;

  // build_mesh(outline, options, mesh) with this builder's memory.
  void build(const Outline& outline, const MeshOptions& options, Mesh& mesh);
  // fill_boundary(outline, options.fill_rule, options.cubic_tolerance).
  Outline boundary(const Outline& outline, const MeshOptions& options);

  struct Scratch;  // (defined inside the library)

 private:
  std::unique_ptr<Scratch> scratch_;
};

// build_mesh into `mesh` with the memory of `builder` (builder.build).
CURVETEXT_API void build_mesh(const Outline& outline, const MeshOptions& options, Mesh& mesh, MeshBuilder& builder);

// Area enclosed by the mesh: interior triangles plus, for each curved triangle,
// the area of its filled side (chord side for convex, outer side otherwise).
CURVETEXT_API double mesh_area(const Mesh& mesh);

// The invariants of docs/design.md section 4, checked on a built mesh.
struct MeshCheck {
  double area_mesh = 0.0;
  double area_outline = 0.0;          // nonzero area of the quadratic outline
  double area_rel_error = 0.0;        // |mesh - outline| / max(|outline|, tiny)
  bool watertight = true;             // every interior edge shared by exactly two faces
  std::size_t hull_overlaps = 0;      // curved triangles overlapping another face
  std::size_t degenerate = 0;         // faces with non-positive area
  std::vector<std::string> problems;  // human-readable, one per violation (capped)
  bool ok() const { return problems.empty(); }
};

// `quadratic_outline` must be the outline the mesh was built from after cubic
// replacement (to_quadratic_outline with the same tolerance). Violations are
// reported in the result, not thrown (Error(Geometry) only when memory runs
// out). Its coordinates are read as build_mesh reads them (tiny ones as 0).
// `rule`: the fill rule the mesh was built with (the outline's area is taken
// under it).
CURVETEXT_API MeshCheck check_mesh(const Mesh& mesh, const Outline& quadratic_outline,
                                   FillRule rule = FillRule::NonZero);

// The boundary of the fill of `outline` under `rule` as contours that neither
// cross nor overlap, the fill on their left (outer contours counter-clockwise
// in a y-up frame, holes clockwise): their nonzero fill and their even-odd
// fill are both the region. Built by build_mesh's crossing resolution (the
// pieces are exact sub-conics, except conics crossing at a point the
// resolver cannot separate, replaced by chords over spans of ~1e-6 of the
// curve). Cubics are replaced by conics within `cubic_tolerance`. Throws what
// build_mesh throws. Thread-safe as build_mesh.
CURVETEXT_API Outline fill_boundary(const Outline& outline, FillRule rule, double cubic_tolerance = 0.25);

}  // namespace curvetext
