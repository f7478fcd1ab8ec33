// An SDL2 window with an OpenGL ES 2.0 context: a small 2D game scene and the
// HUD of the GLFW example (score, FPS counter, wrapped paragraph) drawn with
// curvetext into the window's default framebuffer, between the app's own draws,
// and an SVG icon in the bar drawn each frame through a ShapeDrawing.
#include <GLES2/gl2.h>
#include <SDL.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/glyph_cache.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shape_drawing.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/text_block.hpp"
#include "common/app.hpp"
#include "common/gl_program.hpp"
#include "common/hud.hpp"

namespace {

constexpr const char* kUsage =
    "usage: hud_sdl [--frames N] [--size WxH] [--screenshot FILE.png] [--report] [--no-text]\n"
    "  --frames N      frames to draw, then exit (default 600)\n"
    "  --size WxH      window size in pixels (default 960x600)\n"
    "  --screenshot F  save the last frame's default framebuffer as PNG F (and F.txt)\n"
    "  --report        draw N frames with text and N without; print median/min frame times\n"
    "  --no-text       the app's own scene only\n";

struct Vertex {
  float x, y;        // window pixels
  float r, g, b, a;  // straight alpha
};

void add_rect(std::vector<Vertex>& v, float x, float y, float w, float h, curvetext::Color c) {
  const Vertex a{x, y, c.r, c.g, c.b, c.a}, b{x + w, y, c.r, c.g, c.b, c.a}, d{x + w, y + h, c.r, c.g, c.b, c.a},
      e{x, y + h, c.r, c.g, c.b, c.a};
  for (const Vertex& p : {a, b, d, a, d, e}) v.push_back(p);
}

void add_rect(std::vector<Vertex>& v, const curvetext::Rect& r, curvetext::Color c) {
  add_rect(v, static_cast<float>(r.x), static_cast<float>(r.y), static_cast<float>(r.width),
           static_cast<float>(r.height), c);
}

// The app's own drawing: coloured rectangles in window pixels, from one
// buffer refilled each frame, drawn in three ranges (the scene, the HUD's
// bar and panel, the lives shown in the bar).
class Scene2D {
 public:
  Scene2D();
  ~Scene2D();
  // Fills the buffer for `frame` and binds the program, buffer and attributes.
  void prepare(int frame, int width, int height, const example::Hud& hud);
  // Draw with whatever prepare() bound: text drawn in between must have put
  // it back (GLES2 has no VAOs, so the attribute arrays are the context's).
  void draw_scene() const { glDrawArrays(GL_TRIANGLES, 0, scene_count_); }
  void draw_panels() const { glDrawArrays(GL_TRIANGLES, scene_count_, panels_count_); }
  void draw_lives() const { glDrawArrays(GL_TRIANGLES, scene_count_ + panels_count_, lives_count_); }

 private:
  static constexpr const char* kVertex = R"(#version 100
attribute vec2 a_pixel;
attribute vec4 a_color;
uniform vec2 u_viewport;
varying vec4 v_color;
void main() {
  v_color = a_color;
  gl_Position = vec4(2.0 * a_pixel.x / u_viewport.x - 1.0, 1.0 - 2.0 * a_pixel.y / u_viewport.y, 0.0, 1.0);
})";
  static constexpr const char* kFragment = R"(#version 100
precision mediump float;
varying vec4 v_color;
void main() { gl_FragColor = v_color; })";

  GLuint program_ = 0, vbo_ = 0;
  GLint viewport_ = -1;
  GLsizei scene_count_ = 0, panels_count_ = 0, lives_count_ = 0;
};

Scene2D::Scene2D() {
  program_ = example::link_program(kVertex, kFragment, {{0, "a_pixel"}, {1, "a_color"}});
  viewport_ = glGetUniformLocation(program_, "u_viewport");
  glGenBuffers(1, &vbo_);
}

Scene2D::~Scene2D() {
  glDeleteBuffers(1, &vbo_);
  glDeleteProgram(program_);
}

// Bricks, a paddle and a ball, moving with the frame number (not the clock).
void add_game(std::vector<Vertex>& v, int frame, int width, int height) {
  const float t = static_cast<float>(frame) / 60.0f;
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  constexpr int kColumns = 12, kRows = 6;
  const float brick_w = (w - 40.0f) / kColumns, brick_h = 22.0f;
  for (int row = 0; row < kRows; ++row)
    for (int col = 0; col < kColumns; ++col) {
      const float x = 20.0f + static_cast<float>(col) * brick_w, y = 70.0f + static_cast<float>(row) * (brick_h + 4.0f);
      if ((row * 7 + col * 3 + frame / 20) % 11 == 0) continue;  // bricks knocked out, changing over time
      const float u = static_cast<float>(col) / kColumns, k = static_cast<float>(row) / kRows;
      const curvetext::Color c{0.9f - 0.5f * k, 0.3f + 0.5f * u, 0.35f + 0.5f * k, 1.0f};
      add_rect(v, x + 2.0f, y, brick_w - 4.0f, brick_h, c);
    }
  const float paddle_x = 0.5f * w + 0.35f * w * std::sin(1.3f * t) - 70.0f;
  add_rect(v, paddle_x, h - 40.0f, 140.0f, 14.0f, {0.95f, 0.95f, 0.98f, 1.0f});
  const float ball_x = 0.5f * w + 0.4f * w * std::sin(2.1f * t), ball_y = 0.55f * h + 0.2f * h * std::cos(2.9f * t);
  add_rect(v, ball_x - 8.0f, ball_y - 8.0f, 16.0f, 16.0f, {1.0f, 0.55f, 0.2f, 1.0f});
}

void Scene2D::prepare(int frame, int width, int height, const example::Hud& hud) {
  std::vector<Vertex> v;
  // A gradient floor under the game, then the game.
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  add_rect(v, 0.0f, 0.0f, w, h, {0.10f, 0.16f, 0.24f, 1.0f});
  add_rect(v, 0.0f, 0.6f * h, w, 0.4f * h, {0.16f, 0.22f, 0.30f, 1.0f});
  add_game(v, frame, width, height);
  scene_count_ = static_cast<GLsizei>(v.size());
  add_rect(v, hud.top_bar(), example::Hud::kBarColor);
  add_rect(v, hud.panel(), example::Hud::kPanelColor);
  panels_count_ = static_cast<GLsizei>(v.size()) - scene_count_;
  for (int i = 0; i < 3; ++i)  // lives, in the bar between the score and the FPS counter
    add_rect(v, 0.40f * w + 26.0f * static_cast<float>(i), 16.0f, 16.0f, 16.0f, {1.0f, 0.3f, 0.4f, 1.0f});
  lives_count_ = static_cast<GLsizei>(v.size()) - scene_count_ - panels_count_;

  glUseProgram(program_);
  glUniform2f(viewport_, static_cast<float>(width), static_cast<float>(height));
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(Vertex)), v.data(), GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<const void*>(2 * sizeof(float)));
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
}

// An icon as icon themes write them: a style sheet with currentColor, a
// gradient, a transform, basic shapes and a stroke (docs/svg.md).
constexpr const char* kIcon =
    "<svg xmlns='http://www.w3.org/2000/svg' width='16' height='16' viewBox='0 0 16 16'>"
    "<style>.ColorScheme-Text { color: #f2f4f8 }</style>"
    "<radialGradient id='sun' fx='.35' fy='.35'><stop stop-color='#ffe27a'/><stop offset='1' "
    "stop-color='#f08a24'/></radialGradient>"
    "<circle cx='8' cy='8' r='6.5' fill='url(#sun)'/>"
    "<g class='ColorScheme-Text' transform='rotate(-20 8 8)'>"
    "<path d='M5 9.5q3 2.5 6 0' fill='none' stroke='currentColor' stroke-width='1.2' stroke-linecap='round'/>"
    "<rect x='5' y='5.5' width='1.6' height='2' rx='.8' fill='currentColor'/>"
    "<rect x='9.4' y='5.5' width='1.6' height='2' rx='.8' fill='currentColor'/></g></svg>";
constexpr double kIconPx = 24.0;

// curvetext's part: static text uploaded once, the score and FPS counter
// rebuilt when their text changes; an SVG icon meshed once.
class TextLayer {
 public:
  TextLayer(int width, int height)
      : hud_(fonts_, width, height),
        paragraph_(curvetext::TextBlock::from_paragraph(cache_, hud_.paragraph())),
        icon_(curvetext::ShapeDrawing::from_document(curvetext::parse_svg(kIcon), kIconPx / 16.0)),
        width_(width) {}
  const example::Hud& hud() const { return hud_; }

  void set(const example::HudText& text) {
    if (!score_ || score_text_ != text.score) score_.emplace(cache_, hud_.score_item(text.score));
    if (!fps_ || fps_text_ != text.fps) fps_.emplace(cache_, hud_.fps_item(text.fps));
    score_text_ = text.score;
    fps_text_ = text.fps;
  }
  void draw_score() { score_->draw(renderer_); }
  // In the bar after the lives, each frame in one call; part of the app's
  // scene (drawn with --no-text too).
  void draw_icon() {
    const curvetext::Placement at(kIconPx / 16.0, 0.40 * width_ + 90.0, 12.0);  // the icon's y-up top edge at y 12
    icon_.draw(renderer_, at, curvetext::DrawOptions{});
  }
  void draw_rest() {
    fps_->draw(renderer_);
    const curvetext::Vec2 origin = hud_.paragraph_origin();
    paragraph_.draw(renderer_, origin.x, origin.y,
                    curvetext::DrawOptions(curvetext::Color{}, curvetext::AntiAliasing::Full));
  }

 private:
  curvetext::FontCollection fonts_;
  curvetext::GlyphCache cache_;
  curvetext::Renderer renderer_;
  example::Hud hud_;
  curvetext::TextBlock paragraph_;  // one call draws its runs in their colours
  curvetext::ShapeDrawing icon_;
  int width_ = 0;
  std::optional<example::ItemBatch> score_, fps_;
  std::string score_text_, fps_text_;
};

struct Scene {
  TextLayer text;  // also made with --no-text: the HUD's panels need its layout
  Scene2D app;
  Scene(int width, int height) : text(width, height) {}
};

void draw_frame(Scene& s, int frame, int width, int height, bool with_text, const example::HudText& hud_text) {
  glViewport(0, 0, width, height);
  s.app.prepare(frame, width, height, s.text.hud());
  s.app.draw_scene();
  s.app.draw_panels();
  if (with_text) {
    s.text.set(hud_text);
    s.text.draw_score();
  }
  s.text.draw_icon();
  s.app.draw_lives();  // the app carries on with its own state after curvetext's draws
  if (with_text) s.text.draw_rest();
  example::check_gl("after a frame");
}

struct Window {
  SDL_Window* handle = nullptr;
  SDL_GLContext context = nullptr;
  Window(int width, int height) {
    // Under X11 (Xvfb too) EGL gives the GLES context; GLX may not offer one.
    SDL_SetHint(SDL_HINT_VIDEO_X11_FORCE_EGL, "1");
    if (SDL_Init(SDL_INIT_VIDEO) != 0) throw std::runtime_error(std::string("SDL cannot start: ") + SDL_GetError());
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_ES);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 2);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 0);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    handle = SDL_CreateWindow("curvetext: HUD (SDL2, GLES2)", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, width,
                              height, SDL_WINDOW_OPENGL);
    if (handle) context = SDL_GL_CreateContext(handle);
    if (!context) {
      const std::string error = SDL_GetError();
      if (handle) SDL_DestroyWindow(handle);
      SDL_Quit();
      throw std::runtime_error("SDL cannot make a window with a GLES2 context: " + error);
    }
    SDL_GL_SetSwapInterval(0);  // measure drawing, not the display's refresh
  }
  ~Window() {
    SDL_GL_DeleteContext(context);
    SDL_DestroyWindow(handle);
    SDL_Quit();
  }
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
};

bool quit_requested() {
  SDL_Event event;
  bool quit = false;
  while (SDL_PollEvent(&event))
    if (event.type == SDL_QUIT) quit = true;
  return quit;
}

// Draws `frames` frames and saves the last one to `screenshot` (unless empty);
// returns each frame's drawing time (to glFinish).
example::FrameTimes run(Window& window, Scene& scene, int frames, bool with_text, const std::string& screenshot,
                        int width, int height) {
  example::FrameTimes times;
  double last_start = 0.0, last_frame_ms = 0.0;
  for (int frame = 0; frame < frames; ++frame) {
    const double start = example::now_ms();
    if (frame > 0) last_frame_ms = start - last_start;
    last_start = start;
    const example::HudText hud_text{example::score_text(frame), example::fps_text(last_frame_ms)};
    draw_frame(scene, frame, width, height, with_text, hud_text);
    glFinish();
    times.add(example::now_ms() - start);
    if (frame == frames - 1 && !screenshot.empty())
      example::save_screenshot(example::read_window(width, height), screenshot, frame, hud_text.score, hud_text.fps);
    SDL_GL_SwapWindow(window.handle);
    if (quit_requested()) break;
  }
  return times;
}

// The window, its size in pixels and the scene, for example::run_app.
struct App {
  Window window;
  std::array<int, 2> size;  // the drawable's pixels, which may differ from the window's
  Scene scene;
  App(int w, int h) : window(w, h), size(drawable_size(window)), scene(size[0], size[1]) {}
  static std::array<int, 2> drawable_size(Window& window) {
    std::array<int, 2> s{0, 0};
    SDL_GL_GetDrawableSize(window.handle, &s[0], &s[1]);
    return s;
  }
  example::FrameTimes run(int frames, bool with_text, const std::string& screenshot) {
    return ::run(window, scene, frames, with_text, screenshot, size[0], size[1]);
  }
};

}  // namespace

int main(int argc, char** argv) { return example::run_app<App>(argc, argv, "hud_sdl", kUsage); }
