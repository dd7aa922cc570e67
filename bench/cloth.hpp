// bench/cloth.hpp: the benchmark inputs, generated in code: n x n cloth grids (the paper's section 7 uses
// 11^2 to 81^2 vertices) and random well-shaped hinges.
#pragma once

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "hinge/reference/evaluate.hpp"
#include "hinge/reference/mesh.hpp"

namespace hinge::bench {

// A unit square of n x n vertices, jittered in the plane by up to a tenth of the spacing and bumped out of
// it (z = 0.1 sin(6x) cos(5y), plus a little noise) so that every angle is nonzero; each square split
// along its diagonal into two counter-clockwise faces. Vertices and faces in row order (a spatially
// coherent order, as meshers produce). `seed` varies the jitter: seed 1 serves as the rest state.
inline Mesh cloth(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  Mesh m;
  m.vertices.reserve(static_cast<std::size_t>(n) * n);
  m.faces.reserve(2 * static_cast<std::size_t>(n - 1) * (n - 1));
  const double h = 1.0 / (n - 1);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = (i + jitter(rng)) * h, y = (j + jitter(rng)) * h;
      m.vertices.push_back({x, y, 0.1 * std::sin(6 * x) * std::cos(5 * y) + 0.01 * h * jitter(rng)});
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const Index a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      m.faces.push_back({a, b, d});
      m.faces.push_back({a, d, c});
    }
  return m;
}

// `count` well-shaped hinges (CONVENTIONS.md): random points in a box of side 10^U(-3,3) offset by up to
// 100, kept when hinge::reference::well_shaped accepts them.
inline std::vector<std::array<double, 12>> hinges(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1), decade(-3, 3);
  std::vector<std::array<double, 12>> out;
  while (static_cast<int>(out.size()) < count) {
    std::array<double, 12> x;
    const double scale = std::pow(10.0, decade(rng)), shift = 100 * unit(rng);
    for (double& c : x) c = shift + scale * unit(rng);
    if (reference::well_shaped(x)) out.push_back(x);
  }
  return out;
}

}  // namespace hinge::bench
