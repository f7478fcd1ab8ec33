// What both example apps share besides their text: command-line options,
// frame timing and the screenshot of the window's default framebuffer.
#pragma once

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/image.hpp"

namespace example {

struct AppOptions {
  int frames = 600;  // then the app exits
  int width = 960;   // window size, px
  int height = 600;
  std::string screenshot;  // PNG of the last frame (and its text in <file>.txt); empty: none
  bool report = false;     // time `frames` frames with text and `frames` without, print both
  bool text = true;        // false: the app's own scene only (--no-text)
};

// Parses --frames N, --size WxH, --screenshot FILE, --report, --no-text.
// Prints `usage` and exits with status 2 on anything else.
AppOptions parse_options(int argc, char** argv, const char* usage);

// Per-frame times in milliseconds.
class FrameTimes {
 public:
  void add(double ms) { ms_.push_back(ms); }
  double median() const;
  double min() const;
  std::size_t count() const { return ms_.size(); }

 private:
  std::vector<double> ms_;
};

// One line per measurement, then the text's share:
//   frame time with text: median 4.21 ms, min 3.90 ms (120 frames)
void print_report(const char* app, const FrameTimes& with_text, const FrameTimes& without_text);

// The examples' main: the options, then an `App` made for the window size
// (its window, context and scene) runs its frames: with and without text for
// --report, else once as asked. Errors go to stderr with exit status 1.
// App: App(int width, int height) and
// FrameTimes run(int frames, bool with_text, const std::string& screenshot).
template <class App>
int run_app(int argc, char** argv, const char* name, const char* usage) {
  const AppOptions options = parse_options(argc, argv, usage);
  try {
    App app(options.width, options.height);
    if (options.report) {
      const FrameTimes with_text = app.run(options.frames, true, "");
      const FrameTimes without_text = app.run(options.frames, false, "");
      print_report(name, with_text, without_text);
    } else {
      app.run(options.frames, options.text, options.screenshot);
    }
  } catch (const curvetext::Error& e) {
    std::fprintf(stderr, "%s: curvetext: %s\n", name, e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", name, e.what());
    return 1;
  }
  return 0;
}

// The back buffer of the default framebuffer (call before swapping) as an
// opaque image, row 0 at the top: what the window shows.
curvetext::Image read_window(int width, int height);

// Writes the screenshot and, next to it, what the screenshot checker needs
// to redraw the frame's text (lines "key value": frame, score, fps, and the
// context's GL_VERSION): <path>.txt.
void save_screenshot(const curvetext::Image& image, const std::string& path, int frame, const std::string& score,
                     const std::string& fps);

// Milliseconds on a monotonic clock.
double now_ms();

}  // namespace example
