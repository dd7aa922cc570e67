// Inputs built in code (hinge/core/samples.hpp).
#include "hinge/core/samples.hpp"

#include <cmath>
#include <random>


namespace hinge {

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
