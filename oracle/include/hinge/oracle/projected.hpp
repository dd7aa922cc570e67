// hinge/oracle/projected.hpp: the projected Hessian of a hinge's bending term, evaluated at 256 bits: the exact
// Hessian (hinge_energy's enclosure at 320 bits, its midpoints) with its negative eigenvalues set to zero,
// H_+ = sum_k max(lambda_k, 0) v_k v_k^T, by cyclic Jacobi rotations in MPFR until the off-diagonal part is below
// 2^-256 ||H||, rounded to double. Not certified (the eigendecomposition is not enclosed): the reference of
// the conformance's hessian="projected" (docs/energy-conformance.md), committed with its provenance.
#pragma once

#include <array>

#include "hinge/core/energy.hpp"

namespace hinge::oracle {

// H_+ of psi(X; R) for `parameters` (contract's weight), row-major. Throws as certified_mesh does.
std::array<double, 144> projected_hessian_256(const std::array<double, 12>& x, const std::array<double, 12>& rest,
                                              const EnergyParameters& parameters);

}  // namespace hinge::oracle
