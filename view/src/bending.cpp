// Each hinge's |theta - theta_bar| (hinge/view/bending.hpp), theta by hinge::fast's kernel.
#include "hinge/view/bending.hpp"

#include <cmath>
#include <limits>

#include "hinge/core/errors.hpp"
#include "hinge/fast/hinge_kernel.hpp"

namespace hinge::view {

namespace {

constexpr std::size_t batch = 512;  // hinges per call of the kernel's batch form

std::array<double, 12> coordinates(const std::vector<std::array<double, 3>>& vertices, const Hinge& h) {
  std::array<double, 12> x{};
  for (std::size_t j = 0; j < 4; ++j)
    for (std::size_t c = 0; c < 3; ++c) x[3 * j + c] = vertices[static_cast<std::size_t>(h.x[j])][c];
  return x;
}

}  // namespace

std::vector<double> hinge_angles(const Topology& topology, const std::vector<std::array<double, 3>>& vertices) {
  const std::size_t n = topology.hinges.size();
  std::vector<double> theta(n);
  std::vector<std::array<double, 12>> x(std::min(n, batch));
  std::vector<fast::HingeDerivatives<double>> out(x.size());
  for (std::size_t begin = 0; begin < n; begin += batch) {
    const std::size_t count = std::min(batch, n - begin);
    for (std::size_t i = 0; i < count; ++i) x[i] = coordinates(vertices, topology.hinges[begin + i]);
    try {
      fast::hinge_derivatives<double>(std::span(x.data(), count), std::span(out.data(), count), false);
      for (std::size_t i = 0; i < count; ++i) theta[begin + i] = out[i].theta;
    } catch (const InputError&) {  // a hinge in this batch cannot be evaluated: find it, hinge by hinge
      for (std::size_t i = 0; i < count; ++i) {
        try {
          theta[begin + i] = fast::hinge_derivatives<double>(x[i], false).theta;
        } catch (const InputError&) {
          theta[begin + i] = std::numeric_limits<double>::quiet_NaN();
        }
      }
    }
  }
  return theta;
}

std::vector<double> bending_deviation(const std::vector<double>& theta, const std::vector<double>& theta_bar) {
  std::vector<double> d(theta.size());
  for (std::size_t i = 0; i < theta.size(); ++i) d[i] = std::abs(theta[i] - theta_bar[i]);
  return d;
}

}  // namespace hinge::view
