// A first curvetext program: a window (GLFW, OpenGL ES 2.0), a paragraph laid
// out once, and a TextBlock drawn in the render loop. README.md shows the part
// between the [readme] marks.
//   first_window [FRAMES]   draws FRAMES frames, then one more whose inked
//                           pixels it counts, and exits (default: until closed)
#include <GLES2/gl2.h>  // the app's own GL calls; curvetext makes its calls through the same libGLESv2
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include <curvetext/curvetext.hpp>

namespace {

// The pixels of the frame being drawn (before its swap) darker than mid-grey.
int inked_pixels(int width, int height) {
  std::vector<unsigned char> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  int n = 0;
  for (std::size_t i = 0; i < rgba.size(); i += 4) n += rgba[i] < 128;
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  const int frames = argc > 1 ? std::atoi(argv[1]) : -1;
  if (!glfwInit()) return 1;
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 2);
  glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
  GLFWwindow* window = glfwCreateWindow(640, 240, "curvetext: first window", nullptr, nullptr);
  if (window == nullptr) {
    std::fputs("first_window: GLFW cannot open a window with an OpenGL ES 2.0 context\n", stderr);
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  int status = 0;
  try {
    // [readme]
    // Once: fonts (the default font, DejaVu Sans, then fontconfig's fallback),
    // a paragraph wrapped at 560 px, and its glyph meshes uploaded.
    curvetext::FontCollection fonts;
    curvetext::ParagraphStyle style;
    style.default_style.size_px = 28;
    style.width = 560;
    const curvetext::Paragraph paragraph = curvetext::Paragraph::layout(
        fonts, "Hello, world! This paragraph is drawn from its glyphs' outlines, sharp at any size.", {}, style);
    curvetext::Renderer renderer;  // with the window's GL context current
    curvetext::GlyphCache cache;
    const curvetext::TextBlock text = curvetext::TextBlock::from_paragraph(cache, paragraph);

    // Every frame: the app draws, then the text in one call, top-left at
    // (40, 40) px from the viewport's top-left, y down.
    for (int frame = 0; frame != frames && !glfwWindowShouldClose(window); ++frame) {
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      glViewport(0, 0, width, height);
      glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      text.draw(renderer, 40.0, 40.0, curvetext::DrawOptions{});
      glfwSwapBuffers(window);
      glfwPollEvents();
    }
    // [/readme]
    if (frames > 0) {  // for tests: one more frame, read back before its swap
      int width = 0, height = 0;
      glfwGetFramebufferSize(window, &width, &height);
      glViewport(0, 0, width, height);
      glClear(GL_COLOR_BUFFER_BIT);
      text.draw(renderer, 40.0, 40.0, curvetext::DrawOptions{});
      std::printf("first_window: %d frames, then %d pixels inked\n", frames, inked_pixels(width, height));
    }
  } catch (const curvetext::Error& e) {
    std::fprintf(stderr, "first_window: %s\n", e.what());
    status = 1;
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}
