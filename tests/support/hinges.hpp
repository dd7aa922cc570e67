// tests/support/hinges.hpp: hinges for the unit tests: the check values of CONVENTIONS.md and seeded
// random well-shaped hinges (rotated, scaled over decades, offset from the origin).
#pragma once

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "hinge/reference/evaluate.hpp"

namespace hinge::test {

// CONVENTIONS.md check values: x1 = (0,0,0), x2 = (1,0,0), x0 = (0.5,1,0), x3 = (0.5,-1,0); theta = 0.
inline std::array<double, 12> flat_hinge() { return {0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, -1, 0}; }

// `count` well-shaped hinges (CONVENTIONS.md): random points in a box of side 10^U(-3,3), offset by up to
// `offset` along each axis, kept when hinge::reference::well_shaped accepts them.
inline std::vector<std::array<double, 12>> well_shaped_hinges(int count, unsigned seed, double offset = 100) {
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

}  // namespace hinge::test
