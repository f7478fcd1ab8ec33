#include "common/app.hpp"

#include <GLES2/gl2.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace example {

namespace {

[[noreturn]] void usage_error(const char* usage, const std::string& problem) {
  std::fprintf(stderr, "%s\n%s", problem.c_str(), usage);
  std::exit(2);
}

int positive_int(const char* text, const char* usage) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v <= 0 || v > 1'000'000) usage_error(usage, std::string("bad number: ") + text);
  return static_cast<int>(v);
}

}  // namespace

AppOptions parse_options(int argc, char** argv, const char* usage) {
  AppOptions o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--frames" && has_value) {
      o.frames = positive_int(argv[++i], usage);
    } else if (arg == "--size" && has_value) {
      const std::string v = argv[++i];
      const auto x = v.find('x');
      if (x == std::string::npos) usage_error(usage, "bad size: " + v);
      o.width = positive_int(v.substr(0, x).c_str(), usage);
      o.height = positive_int(v.substr(x + 1).c_str(), usage);
    } else if (arg == "--screenshot" && has_value) {
      o.screenshot = argv[++i];
    } else if (arg == "--report") {
      o.report = true;
    } else if (arg == "--no-text") {
      o.text = false;
    } else if (arg == "--help" || arg == "-h") {
      std::printf("%s", usage);
      std::exit(0);
    } else {
      usage_error(usage, "unknown or incomplete option: " + arg);
    }
  }
  return o;
}

double FrameTimes::median() const {
  if (ms_.empty()) return 0.0;
  std::vector<double> v = ms_;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double FrameTimes::min() const { return ms_.empty() ? 0.0 : *std::min_element(ms_.begin(), ms_.end()); }

void print_report(const char* app, const FrameTimes& with_text, const FrameTimes& without_text) {
  std::printf("%s: GL_RENDERER %s, GL_VERSION %s\n", app, reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
              reinterpret_cast<const char*>(glGetString(GL_VERSION)));
  std::printf("frame time with text:    median %.2f ms, min %.2f ms (%zu frames)\n", with_text.median(),
              with_text.min(), with_text.count());
  std::printf("frame time without text: median %.2f ms, min %.2f ms (%zu frames)\n", without_text.median(),
              without_text.min(), without_text.count());
  std::printf("text adds:               median %.2f ms, min %.2f ms\n", with_text.median() - without_text.median(),
              with_text.min() - without_text.min());
}

curvetext::Image read_window(int width, int height) {
  curvetext::Image image(width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<std::uint8_t> rows(image.rgba.size());
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  // GL's rows go bottom-up; the window's alpha is not shown, so it is dropped.
  const std::size_t stride = static_cast<std::size_t>(width) * 4;
  for (int y = 0; y < height; ++y)
    std::memcpy(image.pixel(0, y), rows.data() + static_cast<std::size_t>(height - 1 - y) * stride, stride);
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  return image;
}

void save_screenshot(const curvetext::Image& image, const std::string& path, int frame, const std::string& score,
                     const std::string& fps) {
  curvetext::write_png(image, path);
  std::ofstream out(path + ".txt");
  out << "frame " << frame << "\nscore " << score << "\nfps " << fps << "\ngl "
      << reinterpret_cast<const char*>(glGetString(GL_VERSION)) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path + ".txt");
}

double now_ms() {
  using clock = std::chrono::steady_clock;
  return std::chrono::duration<double, std::milli>(clock::now().time_since_epoch()).count();
}

}  // namespace example
