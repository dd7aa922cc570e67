// Inputs built in code (hinge/core/samples.hpp).
#include "hinge/core/samples.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

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

Mesh grid_mesh(int nx, int ny, double lx, double ly, const std::array<double, 3>& center, const std::string& plane) {
  if (nx < 2 || ny < 2 || !(lx > 0) || !(ly > 0))
    throw std::invalid_argument("grid: expected nx, ny >= 2 and positive sizes");
  int a = 0, b = 1;
  if (plane == "xz") b = 2;
  else if (plane == "yz") a = 1, b = 2;
  else if (plane != "xy") throw std::invalid_argument("grid: unknown plane '" + plane + "'");
  Mesh m;
  m.vertices.resize(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny));
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      std::array<double, 3> p = center;
      p[static_cast<std::size_t>(a)] += (static_cast<double>(i) / (nx - 1) - 0.5) * lx;
      p[static_cast<std::size_t>(b)] += (static_cast<double>(j) / (ny - 1) - 0.5) * ly;
      m.vertices[static_cast<std::size_t>(i + nx * j)] = p;
    }
  m.faces = grid_faces(nx, ny);
  return m;
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
