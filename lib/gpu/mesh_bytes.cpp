#include "curvetext/renderer.hpp"
#include "gpu/vertex_format.hpp"

namespace curvetext {

std::size_t gpu_bytes(const Mesh& mesh) { return gpu::pack_mesh(mesh).gpu_bytes(); }

}  // namespace curvetext
