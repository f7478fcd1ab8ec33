// corpus_run: the glyph corpus check (support/glyph_corpus.hpp) over every
// glyph (or a stride) of one face, for scripts/corpus.sh. Prints one line per
// failure and one RESULT line; exits 0 when nothing failed, 1 when something
// did, 2 on usage errors, 3 when a glyph crashed the process and 4 when one
// ran past the hard time limit. A crash or a hang is reported on stdout as a
// FAIL line naming the glyph and a "resume" glyph id before the process
// exits, so the driver can go on with the rest of the face (--first, --skip).
// A CHUNK line after each chunk of glyphs carries the counts the driver sums.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/renderer.hpp"
#include "support/glyph_corpus.hpp"

namespace {

using namespace curvetext;

// Glyphs per call of check_corpus: failures are printed (and flushed) after
// each chunk, so a later crash loses at most one chunk's verdicts, which the
// driver re-runs from the chunk's first glyph.
constexpr std::uint32_t kChunkGlyphs = 256;

test::CorpusProgress g_progress;
std::atomic<std::int64_t> g_chunk_first{0};
char g_prefix[1024];  // "FAIL <file> face <n> <variations>"

void write_all(const char* s) {
  std::size_t n = std::strlen(s);
  while (n > 0) {
    const ssize_t w = ::write(1, s, n);
    if (w <= 0) return;
    s += w;
    n -= static_cast<std::size_t>(w);
  }
}

// Async-signal-safe decimal formatting.
void write_number(std::int64_t v) {
  char buf[24];
  int i = 23;
  buf[i] = '\0';
  const bool negative = v < 0;
  std::uint64_t u = negative ? static_cast<std::uint64_t>(-(v + 1)) + 1 : static_cast<std::uint64_t>(v);
  do {
    buf[--i] = static_cast<char>('0' + u % 10);
    u /= 10;
  } while (u != 0 && i > 1);
  if (negative) buf[--i] = '-';
  write_all(buf + i);
}

const char* stage_name(int stage) {
  switch (stage) {
    case 0:
      return "building or checking its mesh";
    case 1:
      return "drawing the page that starts with it";
    default:
      return "computing its reference or comparing";
  }
}

void report_abort(const char* what) {
  std::fflush(stdout);
  write_all(g_prefix);
  write_all(" glyph ");
  write_number(g_progress.glyph.load());
  write_all(": ");
  write_all(what);
  write_all(" while ");
  write_all(stage_name(g_progress.stage.load()));
  write_all(" (resume ");
  write_number(g_chunk_first.load());
  write_all(")\n");
}

extern "C" void on_crash(int signal) {
  char text[64] = "crashed with signal ";
  char* p = text + std::strlen(text);
  if (signal >= 10) *p++ = static_cast<char>('0' + signal / 10);
  *p++ = static_cast<char>('0' + signal % 10);
  *p = '\0';
  report_abort(text);
  ::_exit(3);
}

int usage(const char* message) {
  std::fprintf(stderr,
               "corpus_run: %s\nusage: corpus_run --font FILE [--face N] [--variations wght=100] [--size PX]\n"
               "                  [--first G] [--stride K] [--skip G1,G2] [--hang-seconds S] [--images N]\n"
               "                  [--stats FILE] [--broken drop-triangle] [--all-images yes]\n"
               "       corpus_run --font FILE --face-count yes   (prints the number of faces)\n",
               message);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string path, variations;
  int face = 0, images = 5;
  double size = test::kCorpusSizePx, hang_seconds = 60.0;
  std::uint32_t first = 0, stride = 1;
  std::set<std::uint32_t> skip;
  std::string stats_path;
  bool broken = false, all_images = false, face_count = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) return usage(("missing value for " + a).c_str());
    const char* v = argv[++i];
    if (a == "--font")
      path = v;
    else if (a == "--face")
      face = std::atoi(v);
    else if (a == "--variations")
      variations = v;
    else if (a == "--size")
      size = std::atof(v);
    else if (a == "--first")
      first = static_cast<std::uint32_t>(std::strtoul(v, nullptr, 10));
    else if (a == "--stride")
      stride = static_cast<std::uint32_t>(std::strtoul(v, nullptr, 10));
    else if (a == "--hang-seconds")
      hang_seconds = std::atof(v);
    else if (a == "--images")
      images = std::atoi(v);
    else if (a == "--stats")
      stats_path = v;
    else if (a == "--face-count")
      face_count = std::string(v) == "yes";
    else if (a == "--all-images")
      all_images = std::string(v) == "yes";
    else if (a == "--broken")
      broken = std::string(v) == "drop-triangle";
    else if (a == "--skip") {
      for (const char* p = v; *p;) {
        char* end = nullptr;
        skip.insert(static_cast<std::uint32_t>(std::strtoul(p, &end, 10)));
        if (end == p) break;
        p = *end == ',' ? end + 1 : end;
      }
    } else
      return usage(("unknown option " + a).c_str());
  }
  if (path.empty()) return usage("--font is required");
  if (face_count) {  // for the driver: every face of a collection
    std::printf("%d\n", Font::face_count(path));
    return 0;
  }
  if (!(size > 0) || stride == 0) return usage("bad --size or --stride");
  std::snprintf(g_prefix, sizeof g_prefix, "FAIL %s face %d%s%s", path.c_str(), face, variations.empty() ? "" : " ",
                variations.c_str());

  for (const int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(s, on_crash);
  // Watchdog: a glyph that takes longer than --hang-seconds is reported and
  // the process ends, so one hang cannot stop the corpus.
  std::thread([hang_seconds] {
    for (;;) {
      std::this_thread::sleep_for(std::chrono::milliseconds(250));
      if (g_progress.glyph.load() < 0) continue;
      const std::int64_t now =
          std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
              .count();
      if (static_cast<double>(now - g_progress.since_ns.load()) * 1e-9 > hang_seconds) {
        char text[96];
        std::snprintf(text, sizeof text, "no result after %.3g s (hard time bound)", hang_seconds);
        report_abort(text);
        ::_exit(4);
      }
    }
  }).detach();

  const auto start = std::chrono::steady_clock::now();
  try {
    HeadlessContext context = HeadlessContext::create();
    Renderer renderer;
    Font font = Font::open(path, face);
    if (!variations.empty()) font.set_variations(parse_variations(variations));
    test::CorpusOptions options;
    options.size_px = size;
    options.max_images = images;
    options.progress = &g_progress;
    options.drop_a_triangle = broken;
    options.images_of_passing_glyphs = all_images;
    if (!stats_path.empty()) options.stats = std::fopen(stats_path.c_str(), "w");
    std::string label = path.substr(path.find_last_of('/') + 1);
    label = label.substr(0, label.find_last_of('.')) + "-f" + std::to_string(face);
    for (char& c : variations.empty() ? label : (label += "-" + variations))
      if (c == '=' || c == ',' || c == ' ') c = '_';
    options.label = label;

    test::CorpusResult total;
    std::size_t failed = 0;
    const std::uint32_t count = font.glyph_count();
    for (std::uint32_t chunk = first; chunk < count; chunk += kChunkGlyphs * stride) {
      g_chunk_first.store(chunk);
      std::vector<std::uint32_t> ids;
      for (std::uint32_t g = chunk; g < count && g < chunk + kChunkGlyphs * stride; g += stride)
        if (!skip.count(g)) ids.push_back(g);
      const test::CorpusResult r = test::check_corpus(renderer, font, ids, options);
      g_progress.glyph.store(-1);
      for (const test::GlyphFailure& f : r.failures)
        std::printf("%s glyph %u: %s\n", g_prefix, f.glyph, f.reason.c_str());
      std::printf("CHUNK first %u glyphs %zu empty %zu compared %zu failed %zu\n", chunk, r.glyphs, r.empty, r.compared,
                  r.failed_glyphs);
      std::fflush(stdout);
      failed += r.failed_glyphs;
      total.glyphs += r.glyphs;
      total.empty += r.empty;
      total.compared += r.compared;
      total.max_area_error = std::max(total.max_area_error, r.max_area_error);
      total.sum_edge_mean += r.sum_edge_mean;
      total.seconds_mesh += r.seconds_mesh;
      total.seconds_render += r.seconds_render;
      total.seconds_reference += r.seconds_reference;
      auto keep = [](double v, std::uint32_t g, double& slot, std::uint32_t& where) {
        if (v > slot) {
          slot = v;
          where = g;
        }
      };
      keep(r.worst_edge_mean, r.worst_edge_glyph, total.worst_edge_mean, total.worst_edge_glyph);
      keep(r.worst_blurred, r.worst_blurred_glyph, total.worst_blurred, total.worst_blurred_glyph);
      keep(r.worst_pixel, r.worst_pixel_glyph, total.worst_pixel, total.worst_pixel_glyph);
      keep(r.worst_ink, r.worst_ink_glyph, total.worst_ink, total.worst_ink_glyph);
      keep(r.worst_core, r.worst_core_glyph, total.worst_core, total.worst_core_glyph);
      keep(r.worst_crack, r.worst_crack_glyph, total.worst_crack, total.worst_crack_glyph);
      keep(r.slowest_glyph_seconds, r.slowest_glyph, total.slowest_glyph_seconds, total.slowest_glyph);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf(
        "RESULT %s face %d%s%s glyphs %zu empty %zu compared %zu failed %zu max_area_error %.3g "
        "edge_mean %.4f worst_edge %.4f@%u worst_3x3 %.3f@%u worst_line %.3f@%u worst_pixel %.3f@%u "
        "worst_ink %.2f@%u worst_core %.3f@%u slowest %.3fs@%u seconds %.1f (mesh %.1f render %.1f reference %.1f)\n",
        path.c_str(), face, variations.empty() ? "" : " ", variations.c_str(), total.glyphs, total.empty,
        total.compared, failed, total.max_area_error,
        total.compared ? total.sum_edge_mean / static_cast<double>(total.compared) : 0.0, total.worst_edge_mean,
        total.worst_edge_glyph, total.worst_blurred, total.worst_blurred_glyph, total.worst_crack,
        total.worst_crack_glyph, total.worst_pixel, total.worst_pixel_glyph, total.worst_ink, total.worst_ink_glyph,
        total.worst_core, total.worst_core_glyph, total.slowest_glyph_seconds, total.slowest_glyph, seconds,
        total.seconds_mesh, total.seconds_render, total.seconds_reference);
    return failed == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::printf("%s glyph -1: could not run: %s\n", g_prefix, e.what());
    return 1;
  }
}
