// hinge/view/bending.hpp: what the page colours, each hinge's |theta - theta_bar| (docs/contract.md:
// theta in (-pi, pi], its sign and stencil as in "Hinges in a mesh"), theta by hinge::fast's kernel.
#pragma once

#include <vector>

#include "hinge/core/mesh.hpp"

namespace hinge::view {

// theta of every hinge of `topology` (Topology::hinges order) with the vertex positions `vertices`; NaN for
// a hinge that cannot be evaluated there (a triangle of zero area, a non-finite coordinate).
std::vector<double> hinge_angles(const Topology& topology, const std::vector<std::array<double, 3>>& vertices);

// |theta - theta_bar| hinge by hinge (NaN where either is NaN).
std::vector<double> bending_deviation(const std::vector<double>& theta, const std::vector<double>& theta_bar);

}  // namespace hinge::view
