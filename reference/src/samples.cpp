// Inputs built in code (hinge/reference/samples.hpp).
#include "hinge/reference/samples.hpp"

#include <cmath>
#include <random>

#include "hinge/reference/evaluate.hpp"

namespace hinge {

std::vector<std::array<double, 12>> well_shaped_hinges(int count, unsigned seed, double offset) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1), decade(-3, 3);
  std::vector<std::array<double, 12>> hinges;
  while (static_cast<int>(hinges.size()) < count) {
    std::array<double, 12> x;
    const double scale = std::pow(10.0, decade(rng)), shift = offset * unit(rng);
    for (double& c : x) c = shift + scale * unit(rng);
    if (reference::well_shaped(x)) hinges.push_back(x);
  }
  return hinges;
}

std::vector<std::array<Index, 3>> grid_faces(int nx, int ny) {
  std::vector<std::array<Index, 3>> faces;
  faces.reserve(2 * static_cast<std::size_t>(nx - 1) * static_cast<std::size_t>(ny - 1));
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const Index p = j * nx + i, q = p + 1, s = p + nx, r = s + 1;
      faces.push_back({p, q, r});
      faces.push_back({p, r, s});
    }
  return faces;
}

Mesh cloth(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  Mesh m;
  m.vertices.reserve(static_cast<std::size_t>(n) * n);
  const double h = 1.0 / (n - 1);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (i + jitter(rng)) * h, y = (j + jitter(rng)) * h;
      m.vertices.push_back({x, y, 0.1 * std::sin(6 * x) * std::cos(5 * y) + 0.01 * h * jitter(rng)});
    }
  m.faces = grid_faces(n, n);
  return m;
}

}  // namespace hinge
