// The arrangement of the crossing resolver (resolve.cpp), shared by its
// files: cut points (arrangement_cuts.cpp) and side windings (windings.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "curvetext/geometry.hpp"
#include "tessellate/predicates.hpp"
#include "tessellate/resolve.hpp"

namespace curvetext::detail {

inline Box edge_box(const ArrangementEdge& e) {
  Box box;
  box.add(e.a);
  box.add(e.b);
  if (e.conic) box.add(e.control);
  return box;
}

// Angular order of directions from a common vertex v, counter-clockwise from
// the direction +x (exact: signs of coordinate differences are exact in
// floating point, cross signs by orient2d).
inline bool arrangement_angle_less(Vec2 v, Vec2 p, Vec2 q) {
  auto half = [v](Vec2 r) { return (r.y < v.y || (r.y == v.y && r.x < v.x)) ? 1 : 0; };
  const int hp = half(p), hq = half(q);
  if (hp != hq) return hp < hq;
  return orient2d(v, p, q) > 0;
}

// Splits line edges at the cut points found on them, after snapping the
// points together (cut points closer than the merge distance to an end point
// of any edge become that end point, and to each other the first of them).
// The pieces of a split edge are fresh; other edges keep their flag. Returns
// true when some edge was split.
bool split_at_cuts(std::vector<ArrangementEdge>& edges, std::vector<CutPoint>& cuts, ResolveScratch& scratch);

// Coincident edges become one with the sum of their directed counts; edges
// whose count cancels disappear. The merged edges come in the order of their
// first occurrence. `slots`: scratch for the hash table.
void merge_coincident(const std::vector<ArrangementEdge>& edges, std::vector<ArrangementEdge>& merged,
                      std::vector<std::int32_t>& slots);

// Winding numbers just left and right of each edge of a non-crossing
// arrangement (windings.cpp).
void side_windings(const std::vector<ArrangementEdge>& edges, std::vector<int>& left, std::vector<int>& right,
                   ResolveScratch& scratch);

}  // namespace curvetext::detail
