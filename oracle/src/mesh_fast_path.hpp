// oracle/src/mesh_fast_path.hpp: the mesh oracle's fast path (private to hinge::oracle): every hinge's
// theta, grad theta and Hess theta in the bounded double-double of the hinge oracle's fast path
// (fast_path.hpp), eqs. (1)-(3) summed in the same arithmetic, every global entry decided when its whole
// interval rounds to one double; theta == theta_bar decided exactly where the bounds cannot tell (as at
// rest). All or nothing: any output it cannot decide, any hinge it cannot bound (degenerate, out of
// range, theta and theta_bar distinct but closer than the bounds see), and the energies with sines
// (willmore, bridson) leave the whole mesh to the exact stage and enclosures (mesh.cpp).
#pragma once

#include <optional>

#include "hinge/oracle/mesh.hpp"

namespace hinge::oracle::detail {

std::optional<CertifiedMesh> fast_mesh(const Mesh& deformed, const Mesh& rest, const Topology& topology,
                                       const EnergyParameters& parameters, unsigned request, bool gauss_newton = false);

}  // namespace hinge::oracle::detail
