// Nesting: which non-crossing rings bound the fill under the nonzero rule,
// and which holes belong to which outer ring (docs/design.md section 4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "curvetext/geometry.hpp"
#include "tessellate/rings.hpp"

namespace curvetext::detail {

// Scratch memory of nest_rings, reused from outline to outline.
struct NestScratch {
  enum class Role { Drop, Outer, Hole };
  std::vector<double> area;
  std::vector<Box> box;
  // The rings that contain ring i: container_list[container_start[i] ..
  // container_start[i + 1]).
  std::vector<std::size_t> container_start, container_list;
  std::vector<Role> role;
  std::vector<std::size_t> owner;  // each hole's innermost containing outer ring
};

// Nonzero-rule roles of non-crossing rings: which bound the fill, their
// orientation normalised in place (fill on the left: outer rings
// counter-clockwise, holes clockwise), holes attached to their innermost
// container. Region r is the rings region_rings[region_start[r] ..
// region_start[r + 1]): its outer ring, then its holes; rings bounding no fill
// are in no region.
void nest_rings(std::vector<Ring>& rings, std::vector<std::uint32_t>& region_rings,
                std::vector<std::uint32_t>& region_start, NestScratch& scratch);

}  // namespace curvetext::detail
