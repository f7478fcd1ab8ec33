// Nesting of non-crossing rings (nesting.hpp).
#include "tessellate/nesting.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/assert.hpp"
#include "tessellate/predicates.hpp"

namespace curvetext::detail {

Where point_in_ring(const Ring& ring, Vec2 p) {
  return point_in_polygon(
      ring.size(),
      [&](std::size_t i) {
        return std::pair{ring[i].a, ring_end(ring, i)};
      },
      p);
}

namespace {

Box ring_box(const Ring& ring) {
  Box box;
  for (const Piece& p : ring) box.add(p.a);
  return box;
}

bool box_contains(const Box& outer, const Box& inner) {
  return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && inner.max.x <= outer.max.x &&
         inner.max.y <= outer.max.y;
}

// Ring `inner` lies inside ring `outer` (they do not cross). After hull
// separation no vertex of one ring lies in a curved cap of another, so the
// chord polygon answers for the curved region.
bool ring_inside(const Ring& inner, const Ring& outer) {
  for (const Piece& p : inner) {
    const Where w = point_in_ring(outer, p.a);
    if (w == Where::Inside) return true;
    if (w == Where::Outside) return false;
  }
  // Every vertex on the other ring: an island touching its hole at all its
  // corners (common after resolving crossings), or a duplicate. Ask the
  // middles of the chords; a chord that is not an edge of `outer` has its
  // middle strictly inside or outside it.
  for (std::size_t i = 0; i < inner.size(); ++i) {
    const Where w = point_in_ring(outer, (inner[i].a + ring_end(inner, i)) * 0.5);
    if (w == Where::Inside) return true;
    if (w == Where::Outside) return false;
  }
  return false;  // every chord on the other ring: a duplicate, not nested
}

}  // namespace

// (Piece k of the result is piece n - 1 - k traversed backwards, so it
// starts where that piece ended.)
void reverse_ring(Ring& ring) {
  const std::size_t n = ring.size();
  if (n == 0) return;
  std::reverse(ring.begin(), ring.end());
  // Now ring[k] is the old piece n - 1 - k, whose end is the old piece
  // n - k's start, i.e. the new ring[k - 1].a (cyclically): shift the starts.
  const Vec2 last = ring[n - 1].a;
  for (std::size_t k = n - 1; k > 0; --k) ring[k].a = ring[k - 1].a;
  ring[0].a = last;
}

namespace {

using Role = NestScratch::Role;

// Fills s.area, s.box and the containers of every ring.
void find_containers(const std::vector<Ring>& rings, NestScratch& s) {
  const std::size_t n = rings.size();
  s.area.resize(n);
  s.box.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    s.area[i] = ring_area(rings[i]);
    s.box[i] = ring_box(rings[i]);
  }
  s.container_start.assign(n + 1, 0);
  s.container_list.clear();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j || !box_contains(s.box[j], s.box[i]) || std::fabs(s.area[j]) < std::fabs(s.area[i])) continue;
      if (ring_inside(rings[i], rings[j])) s.container_list.push_back(j);
    }
    s.container_start[i + 1] = s.container_list.size();
  }
}

std::span<const std::size_t> containers(const NestScratch& s, std::size_t i) {
  return std::span<const std::size_t>(s.container_list.data() + s.container_start[i],
                                      s.container_start[i + 1] - s.container_start[i]);
}

// Nonzero rule: winding just outside ring i is the sum of the orientations
// of the rings around it; just inside it adds its own orientation. The ring
// bounds the fill only where exactly one of the two is non-zero.
void assign_roles(std::vector<Ring>& rings, NestScratch& s) {
  const std::size_t n = rings.size();
  s.role.assign(n, Role::Drop);
  for (std::size_t i = 0; i < n; ++i) {
    int outside = 0;
    for (std::size_t j : containers(s, i)) outside += s.area[j] > 0 ? 1 : -1;
    const int inside = outside + (s.area[i] > 0 ? 1 : -1);
    if ((outside != 0) == (inside != 0)) continue;
    s.role[i] = inside != 0 ? Role::Outer : Role::Hole;
    // Normalise: filled side on the left (outer counter-clockwise, holes clockwise).
    const bool ccw = s.area[i] > 0;
    if ((s.role[i] == Role::Outer) != ccw) reverse_ring(rings[i]);
  }
}

// Each hole's region is its innermost containing outer ring.
void find_owners(std::size_t n, NestScratch& s) {
  s.owner.assign(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    if (s.role[i] != Role::Hole) continue;
    std::size_t best = n;
    for (std::size_t j : containers(s, i)) {
      if (s.role[j] == Role::Outer && (best == n || std::fabs(s.area[j]) < std::fabs(s.area[best]))) best = j;
    }
    s.owner[i] = best;  // n: cannot happen for non-crossing rings; the hole is dropped
  }
}

}  // namespace

void nest_rings(std::vector<Ring>& rings, std::vector<std::uint32_t>& region_rings,
                std::vector<std::uint32_t>& region_start, NestScratch& scratch) {
  const std::size_t n = rings.size();
  find_containers(rings, scratch);
  assign_roles(rings, scratch);
  find_owners(n, scratch);
  // Regions in the order of their outer rings, each followed by its holes
  // in ring order.
  region_rings.clear();
  region_start.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (scratch.role[i] != Role::Outer) continue;
    region_start.push_back(static_cast<std::uint32_t>(region_rings.size()));
    region_rings.push_back(static_cast<std::uint32_t>(i));
    for (std::size_t h = 0; h < n; ++h)
      if (scratch.role[h] == Role::Hole && scratch.owner[h] == i) region_rings.push_back(static_cast<std::uint32_t>(h));
  }
  region_start.push_back(static_cast<std::uint32_t>(region_rings.size()));
  CURVETEXT_ASSERT(region_rings.size() <= n);  // each ring in one region at most
}

}  // namespace curvetext::detail
