// Private to tessellate/: positions as slots of hash tables and as sort keys.
// Font coordinates are exact doubles, so equal positions are equal bit for
// bit once -0.0 is made +0.0 (canonical): hashing and ordering the bits
// finds them without comparing doubles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

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
