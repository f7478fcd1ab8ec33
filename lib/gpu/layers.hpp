// Private interface of gpu/ (offscreen layers for compose/'s ShapeDrawing):
// a group of draws rendered into a layer the size of the bound viewport,
// then composited into what was bound before at an opacity, after being
// multiplied by the coverage of a clip mask drawn into a layer of its own.
#pragma once

#include <GLES3/gl3.h>

#include <memory>
#include <vector>

#include "curvetext/image_target.hpp"
#include "gpu/gl_state.hpp"

namespace curvetext::gpu {

// One draw call's layers (ShapeDrawing::draw): made with the application's
// framebuffer bound, it saves the application's GL state and puts it back
// when destroyed (also when a draw throws). Layers nest. The program, the
// quad and a few textures of finished layers are kept in LayerPrograms
// between draws.
class LayerPrograms;

// A layer's framebuffer and texture.
struct LayerTexture {
  GLuint fbo = 0, texture = 0;
  int width = 0, height = 0;
  GLint format = 0;
};

class LayerStack {
 public:
  LayerStack(LayerPrograms& programs);
  ~LayerStack();
  LayerStack(const LayerStack&) = delete;
  LayerStack& operator=(const LayerStack&) = delete;

  // A new layer, cleared to transparent, bound with a viewport of the same
  // size as the target's (pixel (0, 0) is still the viewport's top left).
  void push();
  // The top layer is a clip mask: the layer under it is multiplied by its
  // alpha (the clip's coverage drawn into it since its push()), and it is
  // freed. Needs a layer under it.
  void apply_mask();
  // Composites the top layer (and its mask) at `opacity` into what was bound
  // under it (the layer below, else the application's framebuffer).
  void pop(float opacity);
  std::size_t depth() const { return layers_.size(); }

 private:
  using Layer = LayerTexture;
  void bind_under_top();                          // the layer under the top one, else the application's target
  void draw_quad(GLuint texture, float opacity);  // with the blending set by the caller
  void release(Layer& layer);                     // back to the programs' pool, or deleted
  void clear_bound() const;                       // the layer bound: its viewport, cleared
  LayerPrograms& programs_;
  GlStateBackup state_;
  int width_ = 0, height_ = 0;
  GLint internal_format_ = GL_RGBA;
  GLuint vao_ = 0;
  std::vector<Layer> layers_;
};

// The compositing program and its quad; made on first use with the context
// that draws, deleted with it current (ShapeDrawing's contract).
class LayerPrograms {
 public:
  LayerPrograms() = default;
  ~LayerPrograms();
  LayerPrograms(const LayerPrograms&) = delete;
  LayerPrograms& operator=(const LayerPrograms&) = delete;

 private:
  friend class LayerStack;
  void make(const ContextInfo& info);
  ContextInfo info_;
  // Textures of finished layers, kept for the next draw of the same size
  // (an application drawing every frame allocates none; their framebuffers
  // are made per draw).
  std::vector<LayerTexture> pool_;
  GLuint program_ = 0, quad_ = 0;
  GLint u_texture_ = -1, u_opacity_ = -1;
};

}  // namespace curvetext::gpu
