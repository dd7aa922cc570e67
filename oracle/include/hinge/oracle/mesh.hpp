// hinge/oracle/mesh.hpp: the certified oracle for a whole mesh (hinge oracle --mesh). The energy
// E = sum_i psi_i (eq. (1)), its gradient (eq. (2)) and Hessian (eq. (3)) are enclosed hinge by hinge from the
// exact form of each hinge (exact.hpp), summed in interval arithmetic, and each global entry rounded to
// the nearest double by Ziv's strategy, as for one hinge (oracle.hpp). First (Options::fast_path, the
// default), the same sums in the fast path's bounded double-double: when every output is decided there,
// that is the result (the same doubles), else the whole mesh goes the way just described.
//
// Exact zeros: theta == theta_bar is decided exactly (then psi' = 0 exactly for shells and tan, and
// psi = 0), exactly zero gradient and Hessian entries of theta stay exact, and an entry with no nonzero
// contribution is exactly zero. A global entry that is zero only by cancellation between hinges is
// certified once its enclosure lies within [-2^-1075, 2^-1075] (then it rounds to zero), else flagged.
//
// Energies: shells, tan, willmore, bridson and viscoelastic (with phi_hat = phi_bar), as in
// hinge/core/energy.hpp. The stiffness k is taken as the exact value of the double given.
#pragma once

#include <vector>

#include "hinge/core/energy.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/core/results.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::oracle {

struct CertifiedMesh {
  RoundedMesh rounded;                   // energy, gradient (3n, if requested), Hessian upper triangle (if requested)
  unsigned bits = 0;                     // the working precision the enclosures needed (0: the fast path decided all)
  std::vector<Uncertified> uncertified;  // outputs named "energy", "gradient[i]", "hessian(i,j)" (0-based)
  // sum over hinges of ||g_h||_2 and ||H_h||_F, the hinges' own energy gradients and Hessians (for the
  // summation condition numbers of hinge conform); approximate, from the enclosures' midpoints (or the
  // fast path's values).
  double gradient_contributions = 0, hessian_contributions = 0;
};

// Throws hinge::InputError / hinge::DomainError naming the hinge, as hinge::reference::assemble does;
// std::invalid_argument with Options::binary32 (rounding to float is offered per hinge only).
CertifiedMesh certified_mesh(const Mesh& deformed, const Mesh& rest, const Topology& topology,
                             const EnergyParameters& parameters, unsigned request = want_all,
                             const Options& options = {});

}  // namespace hinge::oracle
