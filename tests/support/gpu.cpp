#include "support/gpu.hpp"

#include <memory>

namespace curvetext::test {

Gpu& gpu() {
  static std::unique_ptr<Gpu> instance = std::make_unique<Gpu>();
  return *instance;
}

}  // namespace curvetext::test
