// hinge/conformance/energy_inputs.hpp: the inputs of the conformance of bending energies (docs/conformance.md,
// "Bending energies"): deformed hinges of the conformance set, each with a rest hinge of every kind.
// Deterministic, as inputs.hpp's: the same doubles on every platform.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace hinge::conformance {

// A deformed hinge X and its rest hinge R, in the contract's labels (x0, x1, x2, x3 each).
struct EnergyCase {
  std::string id;        // "DEFORMED/REST/NN-tag", e.g. "well-shaped/obtuse/03-random"
  std::string category;  // "DEFORMED/REST", e.g. "well-shaped/obtuse"
  std::array<double, 12> x{}, rest{};
};

// A rest hinge's |e_bar| and the areas of its triangles (x0, x1, x2) and (x3, x2, x1), in double, computed from
// the coordinate differences divided by the largest one (no square over- or underflows at any scale).
struct RestShape {
  double edge = 0, area0 = 0, area3 = 0;
};
RestShape rest_shape(const std::array<double, 12>& rest);

// The kinds of rest hinge, in report order:
//   flat        theta_bar = 0 exactly (the four points exactly coplanar, x0 and x3 on either side)
//   obtuse      pi/2 < |theta_bar| <= pi - 0.05, either sign
//   negative    -pi/2 <= theta_bar <= -0.05 (concave)
//   near-cut    pi - 0.05 < |theta_bar| <= pi - 1e-3, either sign
//   at-rest     R = X
//   rest-angle  theta(R) == theta(X) exactly, R another shape: X with x0 and x3 moved within their
//               triangles' planes where that is exact, then scaled by a power of two and turned by a signed
//               permutation of the axes (exact operations); the oracle's exact same_angle confirms it.
// The rest hinges of the first four kinds vary their hinge edge's length, their areas and their altitudes
// independently, and are brought to the deformed hinge's size by a power of two (exact).
const std::vector<std::string>& rest_kinds();

struct EnergyInputs {
  std::vector<EnergyCase> cases;      // deformed categories in categories() order, rest kinds in rest_kinds() order
  std::vector<std::string> left_out;  // the ids of pairs with |theta - theta_bar| > pi (not graded)
};

// `per_category` deformed hinges of each conformance category (spread over it), each with one rest hinge of
// every kind. Pairs with |theta - theta_bar| > pi, judged on the certified angles, are left out and listed.
EnergyInputs energy_inputs(int per_category);

// The deep set's pairs: `per_family` deformed hinges of each hard family of the deep set (inputs.hpp,
// deep_inputs: ids "<family>/deep-NNNN-<tag>"), spread over it, each with a rest hinge of every kind, as above
// (ids "<family>/<kind>/deep-NNNN-<tag>").
EnergyInputs deep_energy_inputs(int per_family);

// The float32 set's pairs: the float32 conformance inputs (inputs.hpp, float32_inputs) with rest hinges of every
// kind, every rest coordinate zero or a normal float.
EnergyInputs float32_energy_inputs(int per_category);

}  // namespace hinge::conformance
