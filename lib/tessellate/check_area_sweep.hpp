// The nonzero area of a closed polygon whose edges may cross, for
// check_mesh's reference area: a Bentley-Ottmann sweep in O((n + k) log n),
// k the crossings, with the exact predicates of predicates.hpp.
//
// Points are swept in (y, x) order (a horizontal edge behaves as one leaning
// right by an infinitesimal). The status is an ordered tree of the edges the
// sweep line meets, left to right; an edge inserted takes the winding on its
// left from its left neighbour (none: 0), and the windings beside an edge
// change only where it crosses another, which the sweep finds as neighbours
// become adjacent (exact test) and swaps at the computed crossing point. The
// area is summed per edge run between such changes, as the integral of x dy
// (relative to the middle of the x range) where the edge bounds the nonzero
// region, plus its cap (area between its arc and chord) in proportion to the
// height covered. A vertex lying exactly on another edge splits that edge
// there (a contour passing through another's vertex crosses it).
#pragma once

#include <cstdint>
#include <queue>
#include <set>
#include <vector>

#include "curvetext/geometry.hpp"
#include "tessellate/rings.hpp"

namespace curvetext::detail {

class AreaSweep {
 public:
  struct Edge {
    Vec2 a, b;                             // in the contour's direction
    double cap = 0.0;                      // area between arc and chord, positive when the arc bulges right of a -> b
    std::uint32_t contour = 0, index = 0;  // position in its (flattened) contour
  };
  AreaSweep() = default;
  AreaSweep(const AreaSweep&) = delete;
  AreaSweep& operator=(const AreaSweep&) = delete;

  // Area of the edges' fill under `rule` (each contour closed). `touching` is set when
  // two edges meet other than as consecutive pieces of one contour at their
  // common end that are not collinear: a crossing, a vertex on another edge,
  // a shared vertex, a collinear overlap.
  double run(const std::vector<Edge>& edges, const std::vector<std::size_t>& contour_size, FillRule rule,
             bool& touching);

 private:
  struct Slot {
    mutable std::uint32_t piece;  // swapped between adjacent nodes at a crossing
  };
  struct Order {
    using is_transparent = void;
    const AreaSweep* sweep;
    bool operator()(Slot a, Slot b) const { return sweep->left_of(a.piece, b.piece); }
    bool operator()(Slot a, Vec2 v) const;  // v strictly right of a
    bool operator()(Vec2 v, Slot a) const;  // v strictly left of a
  };
  using Tree = std::multiset<Slot, Order>;
  struct Piece {
    Vec2 lo, hi;     // sweep order; lo moves up when a vertex splits the piece
    Vec2 from;       // where the current run of windings started
    double cap, dy;  // cap of the whole edge and its height (the cap's share)
    int up;          // +1 when the contour runs lo -> hi
    int w_minus;     // winding on the -x side (sweep left)
    bool active, fresh;
    std::uint32_t edge;
    Tree::iterator at;
  };
  struct Endpoint {
    Vec2 p;
    std::uint32_t piece;
    bool start;
  };
  struct Crossing {
    Vec2 key, at;
    std::uint32_t left, right;
  };
  struct LaterKey {
    bool operator()(const Crossing& a, const Crossing& b) const;
  };

  bool left_of(std::uint32_t a, std::uint32_t b) const;
  int side(const Piece& of, const Piece& other) const;
  bool crosses_ahead(const Piece& left, const Piece& right) const;
  void prepare(const std::vector<Edge>& edges);
  void vertex(std::size_t first, std::size_t last);
  void collect_through(Vec2 v);
  void remove_ending(std::uint32_t id, Vec2 v);
  void insert_starting(Vec2 v);
  void crossing(const Crossing& c);
  void swap_adjacent(Tree::iterator left, Tree::iterator right, Vec2 at);
  void check_pair(Tree::iterator left);
  void close(Piece& p, Vec2 to);
  bool touches_at(std::size_t first, std::size_t last) const;

  const std::vector<Edge>* edges_ = nullptr;
  const std::vector<std::size_t>* contour_size_ = nullptr;
  std::vector<Piece> pieces_;
  std::vector<Endpoint> endpoints_;
  std::vector<std::uint32_t> through_, starting_;
  Tree tree_{Order{this}};
  std::priority_queue<Crossing, std::vector<Crossing>, LaterKey> crossings_;
  Vec2 now_;
  double centre_x_ = 0.0, area_ = 0.0, caps_ = 0.0;
  FillRule rule_ = FillRule::NonZero;
  bool touching_ = false;
};

}  // namespace curvetext::detail
