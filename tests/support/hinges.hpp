// tests/support/hinges.hpp: hinges for the unit tests: the check values of docs/contract.md and seeded
// random well-shaped hinges (rotated, scaled over decades, offset from the origin).
#pragma once

#include <array>
#include <vector>

#include "hinge/core/samples.hpp"
#include "hinge/reference/evaluate.hpp"

namespace hinge::test {

// docs/contract.md check values: x1 = (0,0,0), x2 = (1,0,0), x0 = (0.5,1,0), x3 = (0.5,-1,0); theta = 0.
inline std::array<double, 12> flat_hinge() { return {0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, -1, 0}; }

// Seeded random well-shaped hinges (hinge/reference/evaluate.hpp: the demo's and the benchmark's sampler).
using hinge::reference::well_shaped_hinges;

}  // namespace hinge::test
