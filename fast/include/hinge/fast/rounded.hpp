// hinge/fast/rounded.hpp: hinge::fast in a scalar type chosen at run time, every output rounded to the
// nearest double, in hinge::reference's result types. This is what `hinge eval --method fast --scalar S`
// and `hinge hessian --method fast` call; it keeps the multiprecision templates out of tools/.
// Every scalar type of hinge::reference is available: float, double, long-double, float128, bin128,
// mpfr:BITS.
#pragma once

#include <array>

#include "hinge/fast/pattern.hpp"
#include "hinge/reference/rounded.hpp"

namespace hinge::fast {

// The per-hinge kernel (hinge_kernel.hpp) in `type`. Throws InputError (degenerate or non-finite input)
// or DomainError (a result outside the range of double), as hinge::reference::theta_derivatives_rounded.
reference::RoundedTheta hinge_derivatives_rounded(const ScalarType& type, const std::array<double, 12>& x);

// Algorithm 1 on `rest`, then Algorithm 2 on `deformed` (assemble.hpp) in `type` on `threads` threads,
// rounded to double. Throws as hinge::reference::assemble_rounded does. For double the Hessian is moved
// out, not copied, and it is marked as an Eigen rvalue: assigning the result to another RoundedMesh
// swaps the matrix in instead of copying it (Eigen 3.4's SparseMatrix has no move assignment). Assign
// or use the result; do not copy it (a copy would take the matrix away from it).
reference::RoundedMesh assemble_rounded(const ScalarType& type, const Mesh& deformed, const Mesh& rest,
                                        const Topology& topology, const reference::EnergyParameters& parameters,
                                        unsigned request, int threads,
                                        EdgeOrientation orientation = EdgeOrientation::first_face);

}  // namespace hinge::fast
