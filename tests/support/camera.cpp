#include "support/camera.hpp"

#include <cmath>
#include <numbers>

namespace curvetext::test {

std::array<float, 16> camera_mvp(double aspect) {
  auto mul = [](const std::array<double, 16>& a, const std::array<double, 16>& b) {
    std::array<double, 16> c{};
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row)
        for (int k = 0; k < 4; ++k) c[4 * col + row] += a[4 * k + row] * b[4 * col + k];
    return c;
  };
  const double f = 1.0 / std::tan(25.0 * std::numbers::pi / 180.0), n = 0.1, far = 100.0;
  const std::array<double, 16> projection = {
      f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + n) / (n - far), -1, 0, 0, 2 * far * n / (n - far), 0};
  // look-at from eye e to target t with up +y.
  const double e[3] = {3.0, -2.5, 5.0}, t[3] = {1.0, 0.5, 0.0};
  double fw[3] = {t[0] - e[0], t[1] - e[1], t[2] - e[2]};
  const double fl = std::sqrt(fw[0] * fw[0] + fw[1] * fw[1] + fw[2] * fw[2]);
  for (double& v : fw) v /= fl;
  double side[3] = {fw[1] * 0 - fw[2] * 1, fw[2] * 0 - fw[0] * 0, fw[0] * 1 - fw[1] * 0};  // fw x up
  const double sl = std::sqrt(side[0] * side[0] + side[1] * side[1] + side[2] * side[2]);
  for (double& v : side) v /= sl;
  const double up[3] = {side[1] * fw[2] - side[2] * fw[1], side[2] * fw[0] - side[0] * fw[2],
                        side[0] * fw[1] - side[1] * fw[0]};
  const double dot_s = side[0] * e[0] + side[1] * e[1] + side[2] * e[2];
  const double dot_u = up[0] * e[0] + up[1] * e[1] + up[2] * e[2];
  const double dot_f = fw[0] * e[0] + fw[1] * e[1] + fw[2] * e[2];
  const std::array<double, 16> view = {side[0], up[0], -fw[0], 0, side[1], up[1],  -fw[1], 0,
                                       side[2], up[2], -fw[2], 0, -dot_s,  -dot_u, dot_f,  1};
  const std::array<double, 16> m = mul(projection, view);
  std::array<float, 16> out{};
  for (int i = 0; i < 16; ++i) out[static_cast<std::size_t>(i)] = static_cast<float>(m[static_cast<std::size_t>(i)]);
  return out;
}

}  // namespace curvetext::test
