// Private to tessellate/: K arrays of n doubles laid one after another in a
// scratch vector, for scans written without branches (one array per
// coordinate or box side, read in a row).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace curvetext::detail {

// Resizes `storage` to K * n and returns the start of each array. The
// pointers stay valid until `storage` is resized again.
template <std::size_t K>
std::array<double*, K> columns(std::vector<double>& storage, std::size_t n) {
  storage.resize(K * n);
  std::array<double*, K> starts;
  for (std::size_t k = 0; k < K; ++k) starts[k] = storage.data() + k * n;
  return starts;
}

}  // namespace curvetext::detail
