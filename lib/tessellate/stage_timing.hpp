// Stage-by-stage timing of build_mesh, for finding where preparation time
// goes (bench/glyph_prep_bench --stages). Compiled in only with the CMake
// option CURVETEXT_STAGE_TIMING=ON; otherwise every call below is empty and
// the build is the one we ship. Private to the library; the bench includes it.
//
// The clock is the CPU's time-stamp counter on x86-64 (a few nanoseconds per
// read; the bench converts ticks to microseconds against steady_clock over
// its whole run), steady_clock elsewhere. Each mark adds the time since the
// previous mark (or stage_start) to its stage, so a build that runs twice
// (build_mesh's retry with split rings) adds both runs' times.
#pragma once

#include <cstdint>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#else
#include <chrono>
#endif

namespace curvetext::detail {

enum class MeshStage : int {
  Clean,      // clean_rings: outline -> rings of pieces (cubics split)
  Separate,   // separate_hulls
  Resolve,    // resolve_crossings and hull separation again (overlapping contours only)
  Loops,      // orientation (or nest_rings) and the polygon loops + curved triangles
  Triangles,  // the sweep, or bridging and ear clipping
  Flips,      // Delaunay flips
};
inline constexpr int kMeshStageCount = 6;
inline constexpr const char* kMeshStageNames[kMeshStageCount] = {"clean", "separate",  "resolve",
                                                                 "loops", "triangles", "flips"};

struct MeshStageTicks {
  std::uint64_t last = 0;
  std::uint64_t ticks[kMeshStageCount] = {};
};

inline std::uint64_t stage_clock() {
#if defined(__x86_64__) || defined(__i386__)
  return __rdtsc();
#else
  return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
}

// The clock and this thread's ticks are defined in every build (the bench
// names them in code it discards without the option); only the marks below
// are compiled out. The caller reads and resets the ticks between glyphs.
inline MeshStageTicks& mesh_stage_ticks() {
  thread_local MeshStageTicks ticks;
  return ticks;
}

#if defined(CURVETEXT_STAGE_TIMING)
inline constexpr bool kStageTiming = true;

inline void stage_start() { mesh_stage_ticks().last = stage_clock(); }

inline void stage_mark(MeshStage stage) {
  MeshStageTicks& t = mesh_stage_ticks();
  const std::uint64_t now = stage_clock();
  t.ticks[static_cast<int>(stage)] += now - t.last;
  t.last = now;
}
#else
inline constexpr bool kStageTiming = false;
inline void stage_start() {}
inline void stage_mark(MeshStage) {}
#endif

}  // namespace curvetext::detail
