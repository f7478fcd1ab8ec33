// Lawson flips towards a constrained Delaunay triangulation, the last stage
// of build_mesh (triangulate.hpp): on any triangulation with a list of
// constrained edges, or on the sweep's manifold one without.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "core/assert.hpp"
#include "tessellate/predicates.hpp"
#include "tessellate/triangulate.hpp"

namespace curvetext::detail {
namespace {

// The flips' edge table: every edge of the triangles with the faces on its
// sides, the shared ones stacked as candidates (in triangle order), the
// constrained ones marked fixed.
void index_edges(const std::vector<std::array<std::uint32_t, 3>>& triangles, const std::vector<EdgeKey>& constrained,
                 TriangulateScratch& scratch) {
  EdgeTable& edges = scratch.edges;
  std::vector<EdgeKey>& stack = scratch.flip_stack;
  edges.reset(3 * triangles.size());
  stack.clear();
  stack.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const EdgeKey key = edge_key(triangles[t][k], triangles[t][(k + 1) % 3]);
      EdgeTable::Faces& e = edges.at(key);
      if (e.count < 2) e.face[e.count] = t;
      ++e.count;
      if (e.count == 2) stack.push_back(key);  // candidates in triangle order
    }
  }
  // Constrained edges are marked once in the table instead of being looked up
  // in `constrained` for every candidate popped from the stack.
  // Those not in the mesh (possible after remove_folds or a fallback ear)
  // are the only ones a flip could create: fixed edges never flip, so the
  // others are never removed and re-created. Kept apart (sorted, usually
  // empty) so that a new edge is looked up there instead of in all of them.
  std::vector<EdgeKey>& missing = scratch.missing;
  missing.clear();
  for (const EdgeKey& key : constrained) {
    if (EdgeTable::Faces* e = edges.find(key)) {
      e->fixed = true;
    } else {
      missing.push_back(key);
    }
  }
}

}  // namespace

void delaunay_flips(const std::vector<Vec2>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
                    const std::vector<EdgeKey>& constrained, TriangulateScratch& scratch) {
  index_edges(triangles, constrained, scratch);
  EdgeTable& edges = scratch.edges;
  std::vector<EdgeKey>& stack = scratch.flip_stack;
  const std::vector<EdgeKey>& missing = scratch.missing;
  // Lawson's algorithm terminates with exact predicates; ours are not exact
  // (incircle_sign falls back to long double near zero), so the flip count is capped to guarantee an end.
  std::size_t flips_left = 16 * triangles.size() + 64;
  auto opposite = [&](const std::array<std::uint32_t, 3>& t, std::uint32_t u, std::uint32_t v) {
    for (int k = 0; k < 3; ++k) {
      if (t[k] != u && t[k] != v) return t[k];
    }
    return t[0];
  };
  auto has_directed = [](const std::array<std::uint32_t, 3>& t, std::uint32_t u, std::uint32_t v) {
    for (int k = 0; k < 3; ++k) {
      if (t[k] == u && t[(k + 1) % 3] == v) return true;
    }
    return false;
  };
  // Returns the edge's entry (null if none).
  auto replace_face = [&](EdgeKey key, std::uint32_t from, std::uint32_t to) {
    EdgeTable::Faces* e = edges.find(key);
    if (!e) return e;
    for (int k = 0; k < 2; ++k) {
      if (e->face[k] == from) {
        e->face[k] = to;
        break;
      }
    }
    return e;
  };
  // An edge that is fixed or not shared by two triangles stays so: popping
  // it would do nothing, so it is not pushed.
  auto flippable = [](const EdgeTable::Faces* e) { return e && e->count == 2 && !e->fixed; };
  while (!stack.empty() && flips_left > 0) {
    const EdgeKey key = stack.back();
    stack.pop_back();
    EdgeTable::Faces* e = edges.find(key);
    if (!e || e->count != 2 || e->fixed) continue;
    std::uint32_t t1 = e->face[0], t2 = e->face[1];
    std::uint32_t a = key.first, b = key.second;
    if (!has_directed(triangles[t1], a, b)) std::swap(a, b);
    if (!has_directed(triangles[t1], a, b) || !has_directed(triangles[t2], b, a)) continue;
    const std::uint32_t c = opposite(triangles[t1], a, b);
    const std::uint32_t d = opposite(triangles[t2], a, b);
    if (c == d) continue;
    const Vec2 pa = points[a], pb = points[b], pc = points[c], pd = points[d];
    if (orient2d(pa, pd, pc) <= 0 || orient2d(pd, pb, pc) <= 0) continue;  // quad not strictly convex
    if (incircle_sign(pa, pb, pc, pd) <= 0) continue;
    const EdgeKey cd = edge_key(c, d);
    if (edges.find(cd)) continue;  // would duplicate an existing edge
    triangles[t1] = {a, d, c};
    triangles[t2] = {d, b, c};
    e->count = 0;                               // edge a-b is gone
    EdgeTable::Faces& new_edge = edges.at(cd);  // may move the table: e is not used below
    new_edge.face[0] = t1;
    new_edge.face[1] = t2;
    new_edge.count = 2;
    new_edge.fixed = !missing.empty() && std::binary_search(missing.begin(), missing.end(), cd);
    const bool push_ad = flippable(replace_face(edge_key(a, d), t2, t1));
    const bool push_bc = flippable(replace_face(edge_key(b, c), t1, t2));
    --flips_left;
    if (push_ad) stack.push_back(edge_key(a, d));
    stack.push_back(edge_key(d, b));
    if (push_bc) stack.push_back(edge_key(b, c));
    stack.push_back(edge_key(c, a));
  }
}

// Meshes of up to this many points find twins in a direct table of n^2
// 16-bit entries (128 KiB at most); larger ones hash.
constexpr std::size_t kDirectVertices = 256;

namespace {

// Half-edge h = 4 t + k (k < 3: a shift and a mask instead of a division)
// runs from triangles[t][k] to triangles[t][k + 1]; twin[h] is the half-edge
// running back on the other triangle, or -1.
constexpr std::uint32_t kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};

// twin[h] for h = a -> b is the half-edge b -> a, found by a table lookup
// without branches (whether an edge has a twin, inner or boundary, comes in
// no predictable order; mispredicted branches cost more here than the
// arithmetic). Up to kDirectVertices points the table is indexed directly by
// the pair; larger meshes hash it.
void find_twins(std::size_t n, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                TriangulateScratch& scratch) {
  const std::size_t m = triangles.size();
  std::vector<std::int32_t>& twin = scratch.twin;
  twin.assign(4 * m, -1);
  if (n <= kDirectVertices && 4 * m < 0xffff) {  // (h + 1 fits in 16 bits)
    // Entry a * n + b holds h + 1 for h = a -> b, 0 for none. Every entry
    // written is reset before returning, so the table is all zero between
    // calls and is never cleared as a whole.
    std::vector<std::uint16_t>& direct = scratch.direct;
    if (direct.size() < n * n) direct.assign(n * n, 0);
    for (std::uint32_t t = 0; t < m; ++t)
      for (std::uint32_t k = 0; k < 3; ++k)
        direct[triangles[t][k] * n + triangles[t][kNext[k]]] = static_cast<std::uint16_t>(4 * t + k + 1);
    for (std::uint32_t t = 0; t < m; ++t)
      for (std::uint32_t k = 0; k < 3; ++k)
        twin[4 * t + k] = static_cast<std::int32_t>(direct[triangles[t][kNext[k]] * n + triangles[t][k]]) - 1;
    for (std::uint32_t t = 0; t < m; ++t)
      for (std::uint32_t k = 0; k < 3; ++k) direct[triangles[t][k] * n + triangles[t][kNext[k]]] = 0;
  } else {
    // Open addressing on the directed pair, at most a quarter full, so that a
    // probe rarely goes past its first slot.
    constexpr std::uint64_t kEmptyKey = ~std::uint64_t{0};            // all bits set: filled by memset
    std::vector<std::uint64_t>& keys = scratch.twin_keys;             // a << 32 | b, or kEmptyKey
    std::vector<std::int32_t>& half_edges = scratch.twin_half_edges;  // the half-edge of each key
    int bits = 4;
    while ((std::size_t{1} << bits) < 12 * m) ++bits;
    const std::size_t mask = (std::size_t{1} << bits) - 1;
    keys.resize(mask + 1);
    half_edges.resize(mask + 1);
    std::memset(keys.data(), 0xff, keys.size() * sizeof(std::uint64_t));
    // Each end multiplied by its own odd constant (one product of the packed
    // key would put keys with nearby ends in nearby slots).
    auto slot_of = [&](std::uint32_t a, std::uint32_t b) {
      return static_cast<std::size_t>((a * 0x9e3779b97f4a7c15ull ^ b * 0xc2b2ae3d27d4eb4full) >> (64 - bits));
    };
    for (std::uint32_t t = 0; t < m; ++t) {
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t a = triangles[t][k], b = triangles[t][kNext[k]];
        std::size_t slot = slot_of(a, b);
        while (keys[slot] != kEmptyKey) slot = (slot + 1) & mask;
        keys[slot] = std::uint64_t{a} << 32 | b;
        half_edges[slot] = static_cast<std::int32_t>(4 * t + k);
      }
    }
    for (std::uint32_t t = 0; t < m; ++t) {
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t a = triangles[t][kNext[k]], b = triangles[t][k];
        const std::uint64_t key = std::uint64_t{a} << 32 | b;
        std::size_t slot = slot_of(a, b);
        while ((keys[slot] != key) & (keys[slot] != kEmptyKey)) slot = (slot + 1) & mask;
        const std::int32_t found = -static_cast<std::int32_t>(keys[slot] == key);  // all ones or zero
        twin[4 * t + k] = (half_edges[slot] & found) | ~found;                     // the twin or -1
      }
    }
  }
}

}  // namespace

void delaunay_flips_manifold(const std::vector<Vec2>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
                             TriangulateScratch& scratch) {
  const std::size_t m = triangles.size();
  if (m < 2) return;
  find_twins(points.size(), triangles, scratch);
  std::vector<std::int32_t>& twin = scratch.twin;
  std::vector<std::uint32_t>& stack = scratch.manifold_stack;
  // Every inner edge once (from its first side), written without a branch.
  stack.resize(4 * m);
  std::size_t inner = 0;
  for (std::uint32_t h = 0; h < 4 * m; ++h) {
    stack[inner] = h;
    inner += static_cast<std::size_t>(twin[h] > static_cast<std::int32_t>(h));
  }
  stack.resize(inner);
  auto link = [&](std::uint32_t h, std::int32_t other) {
    twin[h] = other;
    if (other >= 0) twin[static_cast<std::size_t>(other)] = static_cast<std::int32_t>(h);
  };
  std::size_t flips_left = 16 * m + 64;  // as in delaunay_flips
  while (!stack.empty() && flips_left > 0) {
    const std::uint32_t h = stack.back();
    stack.pop_back();
    const std::int32_t g = twin[h];
    // Every twin found runs between the same two points; a half-edge that
    // occurs twice (a non-manifold input: never from the sweep) can leave
    // the pairs one-sided, and those are never flipped.
    if (g < 0 || twin[static_cast<std::size_t>(g)] != static_cast<std::int32_t>(h)) continue;
    const std::uint32_t t1 = h >> 2, k1 = h & 3, t2 = static_cast<std::uint32_t>(g) >> 2,
                        k2 = static_cast<std::uint32_t>(g) & 3;
    const std::uint32_t a = triangles[t1][k1], b = triangles[t1][kNext[k1]], c = triangles[t1][kPrev[k1]];
    const std::uint32_t d = triangles[t2][kPrev[k2]];
    if (c == d) continue;
    const Vec2 pa = points[a], pb = points[b], pc = points[c], pd = points[d];
    // (The incircle test first: most edges of the sweep's triangulation are
    // already locally Delaunay, and it rejects them in one test.)
    if (incircle_sign(pa, pb, pc, pd) <= 0) continue;
    if (orient2d(pa, pd, pc) <= 0 || orient2d(pd, pb, pc) <= 0) continue;  // quad not strictly convex
    const std::int32_t bc = twin[4 * t1 + kNext[k1]], ca = twin[4 * t1 + kPrev[k1]];
    const std::int32_t ad = twin[4 * t2 + kNext[k2]], db = twin[4 * t2 + kPrev[k2]];
    triangles[t1] = {a, d, c};
    triangles[t2] = {d, b, c};
    link(4 * t1 + 0, ad);
    link(4 * t1 + 1, static_cast<std::int32_t>(4 * t2 + 2));
    link(4 * t1 + 2, ca);
    link(4 * t2 + 0, db);
    link(4 * t2 + 1, bc);
    --flips_left;
    for (const std::uint32_t e : {4 * t1 + 0, 4 * t1 + 2, 4 * t2 + 0, 4 * t2 + 1})
      if (twin[e] >= 0) stack.push_back(e);
  }
}

}  // namespace curvetext::detail
