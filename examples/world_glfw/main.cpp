// A GLFW window with a desktop GL 3.3 core context: a coloured board seen by
// a GLM camera that pans, zooms and rotates, a text label lying on the board,
// and a HUD (score, FPS counter, wrapped paragraph) drawn with curvetext into
// the window's default framebuffer, between the app's own draws.
#include <GLES3/gl3.h>  // through libglvnd these reach the current desktop context too
#include <GLFW/glfw3.h>

#include <array>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "curvetext/error.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/glyph_cache.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/text_block.hpp"
#include "common/app.hpp"
#include "common/gl_program.hpp"
#include "common/hud.hpp"
#include "common/world.hpp"

namespace {

constexpr const char* kUsage =
    "usage: world_glfw [--frames N] [--size WxH] [--screenshot FILE.png] [--report] [--no-text]\n"
    "  --frames N      frames to draw, then exit (default 600)\n"
    "  --size WxH      window size in pixels (default 960x600)\n"
    "  --screenshot F  save the last frame's default framebuffer as PNG F (and F.txt)\n"
    "  --report        draw N frames with text and N without; print median/min frame times\n"
    "  --no-text       the app's own scene only\n";

struct Vertex {
  glm::vec3 position;
  glm::vec3 color;
};

// ---- The app's own scene ---------------------------------------------------------

// A board of tiles on z = 0 with a sign for the label, and posts standing on
// it. One buffer: the board and sign first, then the posts.
class WorldScene {
 public:
  explicit WorldScene(const example::WorldLabel& label);
  ~WorldScene();
  // Binds the scene's program and VAO, enables depth testing and draws the
  // board, then the sign as a decal (polygon offset).
  void draw_board(const glm::mat4& view_projection) const;
  // Draws the posts with the program, VAO, uniforms and depth state that
  // draw_board left: text drawn in between must have put them back.
  void draw_posts() const;

 private:
  static constexpr const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_color;
uniform mat4 u_view_projection;
out vec3 v_color;
void main() {
  v_color = a_color;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
})";
  static constexpr const char* kFragment = R"(#version 330 core
in vec3 v_color;
out vec4 frag_color;
void main() { frag_color = vec4(v_color, 1.0); })";

  GLuint program_ = 0, vao_ = 0, vbo_ = 0;
  GLint view_projection_ = -1;
  GLsizei board_count_ = 0, sign_count_ = 0, posts_count_ = 0;
};

void add_quad(std::vector<Vertex>& v, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 color) {
  for (const glm::vec3& p : {a, b, c, a, c, d}) v.push_back({p, color});
}

void add_board(std::vector<Vertex>& v) {
  constexpr int kHalf = 7;
  for (int j = -kHalf; j < kHalf; ++j)
    for (int i = -kHalf; i < kHalf; ++i) {
      const float u = static_cast<float>(i + kHalf) / (2 * kHalf), w = static_cast<float>(j + kHalf) / (2 * kHalf);
      const float shade = ((i + j) & 1) ? 0.78f : 1.0f;  // checkerboard
      const glm::vec3 color = shade * glm::vec3(0.25f + 0.6f * u, 0.45f + 0.35f * w, 0.75f - 0.5f * u);
      const float x = static_cast<float>(i), y = static_cast<float>(j);
      add_quad(v, {x, y, 0}, {x + 1, y, 0}, {x + 1, y + 1, 0}, {x, y + 1, 0}, color);
    }
}

void add_post(std::vector<Vertex>& v, glm::vec2 at, float height, glm::vec3 color) {
  const float r = 0.45f;
  const glm::vec3 p0(at.x - r, at.y - r, 0), p1(at.x + r, at.y - r, 0), p2(at.x + r, at.y + r, 0),
      p3(at.x - r, at.y + r, 0), up(0, 0, height);
  // A lighter top and differently shaded sides, so the box reads as a box.
  add_quad(v, p0 + up, p1 + up, p2 + up, p3 + up, color);
  add_quad(v, p0, p1, p1 + up, p0 + up, 0.8f * color);
  add_quad(v, p1, p2, p2 + up, p1 + up, 0.65f * color);
  add_quad(v, p2, p3, p3 + up, p2 + up, 0.5f * color);
  add_quad(v, p3, p0, p0 + up, p3 + up, 0.7f * color);
}

WorldScene::WorldScene(const example::WorldLabel& label) {
  program_ = example::link_program(kVertex, kFragment, {});
  view_projection_ = glGetUniformLocation(program_, "u_view_projection");
  std::vector<Vertex> v;
  add_board(v);
  board_count_ = static_cast<GLsizei>(v.size());
  const glm::vec2 a = label.sign_min, b = label.sign_max;
  add_quad(v, {a.x, a.y, 0}, {b.x, a.y, 0}, {b.x, b.y, 0}, {a.x, b.y, 0}, {0.97f, 0.94f, 0.84f});
  sign_count_ = static_cast<GLsizei>(v.size()) - board_count_;
  add_post(v, {-5.5f, 5.5f}, 2.2f, {0.95f, 0.35f, 0.3f});
  add_post(v, {5.5f, 5.5f}, 1.6f, {0.3f, 0.8f, 0.95f});
  add_post(v, {-5.5f, -5.5f}, 1.2f, {0.95f, 0.8f, 0.25f});
  add_post(v, {5.5f, -5.5f}, 1.8f, {0.7f, 0.45f, 0.95f});
  add_post(v, {0.0f, 6.0f}, 2.6f, {0.4f, 0.9f, 0.45f});
  posts_count_ = static_cast<GLsizei>(v.size()) - board_count_ - sign_count_;

  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(Vertex)), v.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, color)));
  glBindVertexArray(0);
}

WorldScene::~WorldScene() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteProgram(program_);
}

void WorldScene::draw_board(const glm::mat4& view_projection) const {
  glUseProgram(program_);
  glUniformMatrix4fv(view_projection_, 1, GL_FALSE, glm::value_ptr(view_projection));
  glBindVertexArray(vao_);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDrawArrays(GL_TRIANGLES, 0, board_count_);
  glEnable(GL_POLYGON_OFFSET_FILL);  // the sign lies on the board: pull it forward
  glPolygonOffset(-1.0f, -1.0f);
  glDrawArrays(GL_TRIANGLES, board_count_, sign_count_);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

void WorldScene::draw_posts() const { glDrawArrays(GL_TRIANGLES, board_count_ + sign_count_, posts_count_); }

// Translucent rectangles in window pixels (the HUD's bar and panel).
class Overlay {
 public:
  Overlay();
  ~Overlay();
  void draw(const curvetext::Rect& rect, const curvetext::Color& color, int width, int height) const;

 private:
  static constexpr const char* kVertex = R"(#version 330 core
layout(location = 0) in vec2 a_pixel;
uniform vec2 u_viewport;
void main() { gl_Position = vec4(2.0 * a_pixel.x / u_viewport.x - 1.0, 1.0 - 2.0 * a_pixel.y / u_viewport.y, 0.0, 1.0); })";
  static constexpr const char* kFragment = R"(#version 330 core
uniform vec4 u_color;
out vec4 frag_color;
void main() { frag_color = u_color; })";
  GLuint program_ = 0, vao_ = 0, vbo_ = 0;
  GLint viewport_ = -1, color_ = -1;
};

Overlay::Overlay() {
  program_ = example::link_program(kVertex, kFragment, {});
  viewport_ = glGetUniformLocation(program_, "u_viewport");
  color_ = glGetUniformLocation(program_, "u_color");
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, 12 * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindVertexArray(0);
}

Overlay::~Overlay() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteProgram(program_);
}

void Overlay::draw(const curvetext::Rect& r, const curvetext::Color& c, int width, int height) const {
  const float x0 = static_cast<float>(r.x), y0 = static_cast<float>(r.y);
  const float x1 = static_cast<float>(r.x + r.width), y1 = static_cast<float>(r.y + r.height);
  const float corners[12] = {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1};
  glUseProgram(program_);
  glUniform2f(viewport_, static_cast<float>(width), static_cast<float>(height));
  glUniform4f(color_, c.r, c.g, c.b, c.a);
  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof corners, corners);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDrawArrays(GL_TRIANGLES, 0, 6);
}

// ---- Text ------------------------------------------------------------------------

// Everything curvetext needs, made once the context is current. Static text
// (the paragraph, the label) is uploaded once; the score and FPS counter are
// rebuilt when their text changes (their glyph meshes come from the cache).
class TextLayer {
 public:
  TextLayer(int width, int height)
      : hud_(fonts_, width, height),
        label_(example::world_label(fonts_.resolve(example::kFontPath))),
        label_block_(cache_, label_.text),
        paragraph_(curvetext::TextBlock::from_paragraph(cache_, hud_.paragraph())) {}

  const example::Hud& hud() const { return hud_; }
  const example::WorldLabel& label() const { return label_; }

  void draw_label(const glm::mat4& view_projection, int width, int height) {
    label_block_.draw(renderer_, example::label_placement(label_, view_projection, width, height));
  }
  void draw_hud(const example::HudText& text) {
    update(score_, score_text_, text.score, [&] { return hud_.score_item(text.score); });
    update(fps_, fps_text_, text.fps, [&] { return hud_.fps_item(text.fps); });
    score_->draw(renderer_);
    fps_->draw(renderer_);
    const curvetext::Vec2 origin = hud_.paragraph_origin();
    paragraph_.draw(renderer_, origin.x, origin.y,
                    curvetext::DrawOptions(curvetext::Color{}, curvetext::AntiAliasing::Full));
  }

 private:
  template <class MakeItem>
  void update(std::optional<example::ItemBatch>& block, std::string& shown, const std::string& text, MakeItem make) {
    if (block && shown == text) return;
    block.emplace(cache_, make());
    shown = text;
  }

  curvetext::FontCollection fonts_;
  curvetext::GlyphCache cache_;
  curvetext::Renderer renderer_;
  example::Hud hud_;
  example::WorldLabel label_;
  example::ItemBatch label_block_;
  curvetext::TextBlock paragraph_;  // one call draws its runs in their colours
  std::optional<example::ItemBatch> score_, fps_;
  std::string score_text_, fps_text_;
};

// ---- The frame -------------------------------------------------------------------

struct Scene {
  TextLayer text;  // also made with --no-text: the HUD's panels need its layout
  WorldScene world;
  Overlay overlay;

  Scene(int width, int height) : text(width, height), world(text.label()) {}
};

void draw_frame(Scene& s, int frame, int width, int height, bool with_text, const example::HudText& hud_text) {
  glViewport(0, 0, width, height);
  glClearColor(0.12f, 0.14f, 0.2f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  const glm::mat4 view_projection = example::camera_at(frame, width, height);
  s.world.draw_board(view_projection);
  if (with_text) s.text.draw_label(view_projection, width, height);
  s.world.draw_posts();  // with the state draw_board set: curvetext put it back
  s.overlay.draw(s.text.hud().top_bar(), example::Hud::kBarColor, width, height);
  s.overlay.draw(s.text.hud().panel(), example::Hud::kPanelColor, width, height);
  if (with_text) s.text.draw_hud(hud_text);
  example::check_gl("after a frame");
}

struct Window {
  GLFWwindow* handle = nullptr;
  Window(int width, int height) {
    if (!glfwInit()) throw std::runtime_error("GLFW cannot start (no display?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    handle = glfwCreateWindow(width, height, "curvetext: world (GLFW, GL 3.3 core)", nullptr, nullptr);
    if (!handle) {
      glfwTerminate();
      throw std::runtime_error("GLFW cannot make a window with a GL 3.3 core context");
    }
    glfwMakeContextCurrent(handle);
    glfwSwapInterval(0);  // measure drawing, not the display's refresh
  }
  ~Window() {
    glfwDestroyWindow(handle);
    glfwTerminate();
  }
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;
};

// Draws `frames` frames and saves the last one to `screenshot` (unless empty);
// returns each frame's drawing time (to glFinish).
example::FrameTimes run(Window& window, Scene& scene, int frames, bool with_text, const std::string& screenshot,
                        int width, int height) {
  example::FrameTimes times;
  double last_start = 0.0, last_frame_ms = 0.0;
  for (int frame = 0; frame < frames && !glfwWindowShouldClose(window.handle); ++frame) {
    const double start = example::now_ms();
    if (frame > 0) last_frame_ms = start - last_start;
    last_start = start;
    const example::HudText hud_text{example::score_text(frame), example::fps_text(last_frame_ms)};
    draw_frame(scene, frame, width, height, with_text, hud_text);
    glFinish();
    times.add(example::now_ms() - start);
    if (frame == frames - 1 && !screenshot.empty())
      example::save_screenshot(example::read_window(width, height), screenshot, frame, hud_text.score, hud_text.fps);
    glfwSwapBuffers(window.handle);
    glfwPollEvents();
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
    glfwGetFramebufferSize(window.handle, &s[0], &s[1]);
    return s;
  }
  example::FrameTimes run(int frames, bool with_text, const std::string& screenshot) {
    return ::run(window, scene, frames, with_text, screenshot, size[0], size[1]);
  }
};

}  // namespace

int main(int argc, char** argv) { return example::run_app<App>(argc, argv, "world_glfw", kUsage); }
