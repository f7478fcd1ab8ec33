// Private to tessellate/: positions as slots of hash tables and as sort keys.
// Font coordinates are exact doubles, so equal positions are equal bit for
// bit once -0.0 is made +0.0 (canonical): hashing and ordering the bits
// finds them without comparing doubles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "curvetext/geometry.hpp"

namespace curvetext::detail {

// Signed zero would give equal positions different bit patterns (and so
// different slots, keys and vertex indices); adding +0.0 turns -0.0 into
// +0.0.
inline Vec2 canonical(Vec2 p) { return {p.x + 0.0, p.y + 0.0}; }

// A hash of a canonical position's bits for tables of 2^bits slots. Font
// coordinates are short binary numbers whose low mantissa bits are zero:
// multiply (Fibonacci hashing) and keep the top bits, which every input bit
// reaches.
inline std::size_t position_hash(Vec2 p, int bits) {
  std::uint64_t x, y;
  std::memcpy(&x, &p.x, sizeof x);
  std::memcpy(&y, &p.y, sizeof y);
  return static_cast<std::size_t>(((x * 0x9e3779b97f4a7c15ull) ^ (y * 0xc2b2ae3d27d4eb4full)) >> (64 - bits));
}

// Bits of an open-addressing table for `count` entries, at most a quarter
// full, so that a probe rarely goes past its first slot (a probe loop of
// unpredictable length costs a misprediction).
inline int position_table_bits(std::size_t count) {
  int bits = 4;
  while ((std::size_t{1} << bits) < 4 * count) ++bits;
  return bits;
}

// Items 0, 1, ... at positions at(i), looked up by position: the first item
// added at each position. Open addressing with linear probing over the
// caller's scratch `slots` (an item, or -1; the table is valid until they are
// resized), sized by position_table_bits for `count` items.
template <class PositionOf>
class FirstAtPosition {
 public:
  FirstAtPosition(std::vector<std::int32_t>& slots, std::size_t count, PositionOf at)
      : at_(at), bits_(position_table_bits(count)), mask_((std::size_t{1} << bits_) - 1) {
    slots.assign(mask_ + 1, -1);
    slots_ = slots.data();
  }

  // Item i, unless an earlier item holds its position: the first item there
  // (i itself when it is new).
  std::uint32_t add(std::uint32_t i) {
    const Vec2 p = at_(i);
    for (std::size_t slot = position_hash(canonical(p), bits_);; slot = (slot + 1) & mask_) {
      const std::int32_t first = slots_[slot];
      if (first < 0) {
        slots_[slot] = static_cast<std::int32_t>(i);
        return i;
      }
      if (at_(static_cast<std::uint32_t>(first)) == p) return static_cast<std::uint32_t>(first);
    }
  }

  // The first item added at p, or -1.
  std::int32_t find(Vec2 p) const {
    for (std::size_t slot = position_hash(canonical(p), bits_);; slot = (slot + 1) & mask_) {
      const std::int32_t first = slots_[slot];
      if (first < 0 || at_(static_cast<std::uint32_t>(first)) == p) return first;
    }
  }

 private:
  std::int32_t* slots_;  // the caller's storage
  PositionOf at_;
  int bits_;
  std::size_t mask_;
};

// A 128-bit unsigned integer (a GCC and Clang extension; marked so that
// -Wpedantic accepts it).
__extension__ typedef unsigned __int128 Uint128;

// A double's bits as an unsigned integer of the same order (-0.0 as +0.0).
inline std::uint64_t ordered_bits(double v) {
  v += 0.0;
  std::uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return (bits >> 63) != 0 ? ~bits : bits | (std::uint64_t{1} << 63);
}

// A position as one integer ordered as (y, x): one integer comparison orders
// two points, where comparing y and then x costs two unpredictable branches.
inline Uint128 position_key(Vec2 p) { return static_cast<Uint128>(ordered_bits(p.y)) << 64 | ordered_bits(p.x); }

}  // namespace curvetext::detail
