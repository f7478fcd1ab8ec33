// The band path on OpenGL ES 2.0 contexts (docs/design.md section 9): when a
// context takes it, the layout of its quads, and their draw.
#include "gpu/bands_es2.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>

#include "core/tolerances.hpp"
#include "curvetext/error.hpp"
#include "gpu/batch_impl.hpp"
#include "gpu/gl_state.hpp"

namespace curvetext::gpu {

// The shader's float indices are exact below 2^24 (a highp float's 24-bit
// significand): every texel of a page must be, and the texture coordinates
// (i + 0.5) / width must stay exact too.
static_assert(static_cast<long long>(kMaxBandPageRows) * kBandTextureWidth <= (1ll << 24),
              "band pages must stay within the GLES 2 program's exact float indices");
// shaders/bands_es2.frag.glsl reads the entries in runs of 16.
static_assert(tolerance::kEs2BandEntryCap % 16 == 0, "the GLES 2 loop bound is a whole number of runs");
static_assert(kBandQuadsPerDraw * 4 <= 65536, "band quads are drawn with 16-bit indices");

namespace {

std::atomic<bool> allowed{true};

bool has_extension(const char* name) {
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  if (extensions == nullptr) return false;
  const std::size_t len = std::strlen(name);
  for (const char* p = std::strstr(extensions, name); p != nullptr; p = std::strstr(p + len, name))
    if ((p == extensions || p[-1] == ' ') && (p[len] == '\0' || p[len] == ' ')) return true;
  return false;
}

}  // namespace

bool es2_band_context() {
  if (!allowed.load(std::memory_order_relaxed)) return false;
  const ContextInfo info = ContextInfo::current();
  if (!info.gles || info.gl3()) return false;
  GLint range[2] = {0, 0}, precision = 0;
  glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &precision);
  // (0, 0, 0) where the fragment stage has no highp at all.
  if (precision < 23 || range[0] < 62 || range[1] < 62) return false;
  return has_extension("GL_OES_texture_float");
}

void set_es2_bands_allowed(bool allowed_now) { allowed.store(allowed_now, std::memory_order_relaxed); }

int most_band_entries(const GlyphBands& bands) {
  int most = 0;
  const int count = (1 << bands.levels) - 1;
  for (int b = 0; b < count; ++b) {
    const auto& header = bands.texels[static_cast<std::size_t>(1 + b / 2)];
    most = std::max(most, static_cast<int>(header[static_cast<std::size_t>(2 * (b % 2) + 1)]));
  }
  return most;
}

std::vector<float> expand_band_quads(std::span<const float> instances) {
  static constexpr float kCorners[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  std::vector<float> out;
  out.reserve(instances.size() / 8 * 4 * kBandQuadVertexFloats);
  for (std::size_t i = 0; i + 8 <= instances.size(); i += 8)
    for (const auto& corner : kCorners) {
      out.insert(out.end(), {corner[0], corner[1]});
      out.insert(out.end(), instances.begin() + static_cast<std::ptrdiff_t>(i),
                 instances.begin() + static_cast<std::ptrdiff_t>(i + 8));
    }
  return out;
}

GLuint make_band_quad_indices() {
  std::vector<std::uint16_t> indices;
  indices.reserve(6 * kBandQuadsPerDraw);
  for (int q = 0; q < kBandQuadsPerDraw; ++q) {
    const auto v = static_cast<std::uint16_t>(4 * q);
    indices.insert(indices.end(), {v, static_cast<std::uint16_t>(v + 1), static_cast<std::uint16_t>(v + 2),
                                   static_cast<std::uint16_t>(v + 2), static_cast<std::uint16_t>(v + 1),
                                   static_cast<std::uint16_t>(v + 3)});
  }
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  if (buffer == 0) throw Error(ErrorCode::Gl, "glGenBuffers failed (is a GL context current?)");
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer);  // the caller's draw keeps it bound
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(indices[0])), indices.data(),
               GL_STATIC_DRAW);
  return buffer;
}

void draw_band_quads(GLint first, GLsizei count) {
  constexpr GLsizei kStride = kBandQuadVertexFloats * sizeof(float);
  for (GLsizei done = 0; done < count; done += kBandQuadsPerDraw) {
    const auto vertex = static_cast<std::uintptr_t>(first + done) * 4u * kStride;
    const auto at = [&](std::size_t floats) { return reinterpret_cast<const void*>(vertex + floats * sizeof(float)); };
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, kStride, at(0));
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, kStride, at(2));
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, kStride, at(6));
    const GLsizei quads = std::min(count - done, static_cast<GLsizei>(kBandQuadsPerDraw));
    glDrawElements(GL_TRIANGLES, 6 * quads, GL_UNSIGNED_SHORT, nullptr);
  }
}

}  // namespace curvetext::gpu
