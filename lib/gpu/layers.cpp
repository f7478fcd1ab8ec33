// Offscreen layers: SVG's group opacity and clip-path coverage masks
// (layers.hpp, docs/svg.md).
#include "gpu/layers.hpp"

#include <cstring>
#include <string>

#include "curvetext/error.hpp"
#include "gpu/gl_util.hpp"
#include "gpu/shader_sources.hpp"

namespace curvetext::gpu {

void LayerPrograms::make(const ContextInfo& info) {
  if (program_ != 0) return;
  info_ = info;
  const GLuint program = glsl1_program(shader_source::layer_vert_glsl, shader_source::layer_frag_glsl, info.gles,
                                       {"a_clip"}, "the layer program");
  program_ = program;
  u_texture_ = glGetUniformLocation(program, "u_texture");
  u_opacity_ = glGetUniformLocation(program, "u_opacity");
  const GLfloat corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
  glGenBuffers(1, &quad_);
  glBindBuffer(GL_ARRAY_BUFFER, quad_);
  glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
}

LayerPrograms::~LayerPrograms() {
  for (LayerTexture& t : pool_) {
    glDeleteFramebuffers(1, &t.fbo);
    glDeleteTextures(1, &t.texture);
  }
  if (program_ != 0) glDeleteProgram(program_);
  if (quad_ != 0) glDeleteBuffers(1, &quad_);
}

LayerStack::LayerStack(LayerPrograms& programs) : programs_(programs), state_(ContextInfo::current()) {
  const ContextInfo info = ContextInfo::current();
  programs_.make(info);
  if (info.gl3()) glGenVertexArrays(1, &vao_);  // a container object: this context's own
  width_ = state_.viewport()[2];
  height_ = state_.viewport()[3];
  // The layers blend as the target does: in linear light where it is sRGB-encoded.
  internal_format_ = bound_framebuffer_blending(info.gles, info.gl3(), state_.draw_framebuffer()) == Blending::Linear
                         ? GL_SRGB8_ALPHA8
                         : GL_RGBA;
}

LayerStack::~LayerStack() {
  for (Layer& l : layers_) release(l);
  if (vao_ != 0) glDeleteVertexArrays(1, &vao_);
}

namespace {

// Textures kept between draws: a group and its clip mask take two; deeper
// nests allocate what is beyond.
constexpr std::size_t kMaxPooledLayers = 4;

void destroy(LayerTexture& t) {
  if (t.fbo != 0) glDeleteFramebuffers(1, &t.fbo);
  if (t.texture != 0) glDeleteTextures(1, &t.texture);
  t = LayerTexture{};
}

}  // namespace

// Framebuffers (container objects, not shared between contexts) are made
// per draw; textures (shared) go back to the pool.
void LayerStack::release(Layer& layer) {
  if (layer.fbo != 0) glDeleteFramebuffers(1, &layer.fbo);
  layer.fbo = 0;
  if (programs_.pool_.size() < kMaxPooledLayers)
    programs_.pool_.push_back(layer);
  else
    destroy(layer);
  layer = Layer{};
}

void LayerStack::push() {
  if (width_ <= 0 || height_ <= 0) throw Error(ErrorCode::InvalidArgument, "a layer needs a viewport with pixels");
  std::vector<LayerTexture>& pool = programs_.pool_;
  Layer l;
  for (std::size_t i = 0; i < pool.size() && l.texture == 0; ++i)
    if (pool[i].width == width_ && pool[i].height == height_ && pool[i].format == internal_format_) {
      l = pool[i];
      pool.erase(pool.begin() + static_cast<std::ptrdiff_t>(i));
    }
  if (l.texture == 0) {
    l.width = width_;
    l.height = height_;
    l.format = internal_format_;
    l.texture = new_texture(internal_format_, GL_RGBA, width_, height_);
  }
  if (const GLenum err = glGetError(); err != GL_NO_ERROR) {
    destroy(l);
    throw Error(ErrorCode::Gl, "cannot allocate a " + std::to_string(width_) + "x" + std::to_string(height_) +
                                   " layer texture (GL error " + hex(err) + ")");
  }
  glGenFramebuffers(1, &l.fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, l.fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, l.texture, 0);
  if (const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER); status != GL_FRAMEBUFFER_COMPLETE) {
    destroy(l);
    throw Error(ErrorCode::Gl, "layer framebuffer incomplete (status " + hex(status) + ")");
  }
  layers_.push_back(l);
  clear_bound();
}

void LayerStack::clear_bound() const {
  glViewport(0, 0, width_, height_);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

void LayerStack::bind_under_top() {
  if (layers_.size() >= 2) {
    glBindFramebuffer(GL_FRAMEBUFFER, layers_[layers_.size() - 2].fbo);
    glViewport(0, 0, width_, height_);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  } else {
    state_.apply_target();
  }
  // A full-viewport quad at no particular depth: not depth-tested, and it
  // writes no depth.
  glDisable(GL_DEPTH_TEST);
  glDepthMask(GL_FALSE);
}

void LayerStack::draw_quad(GLuint texture, float opacity) {
  const LayerPrograms& p = programs_;
  glUseProgram(p.program_);
  if (vao_ != 0) glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, p.quad_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture);
  glUniform1i(p.u_texture_, 0);
  glUniform1f(p.u_opacity_, opacity);
  glEnable(GL_BLEND);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glDisableVertexAttribArray(0);
}

void LayerStack::apply_mask() {
  if (layers_.size() < 2) throw Error(ErrorCode::InvalidArgument, "a clip mask needs a layer under it");
  bind_under_top();
  glBlendFunc(GL_ZERO, GL_SRC_ALPHA);  // dst * the mask's coverage
  draw_quad(layers_.back().texture, 1.0f);
  release(layers_.back());
  layers_.pop_back();
}

void LayerStack::pop(float opacity) {
  if (layers_.empty()) throw Error(ErrorCode::InvalidArgument, "no layer to composite");
  bind_under_top();
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied source-over
  draw_quad(layers_.back().texture, opacity);
  release(layers_.back());
  layers_.pop_back();
}

}  // namespace curvetext::gpu
