// hinge/fast/rounded.hpp: hinge::fast's per-hinge kernel in a scalar type chosen at run time, every output
// rounded to the nearest double, in hinge::reference's result types: what `hinge eval --method fast
// --scalar S` calls (the mesh: hinge::methods::MeshEvaluator). Every scalar type of hinge::reference is
// available: float, double, long-double, dd, qd, float128, bin128, mpfr:BITS.
#pragma once

#include <array>

#include "hinge/core/rounding.hpp"

namespace hinge::fast {

// The per-hinge kernel (hinge_kernel.hpp) in `type`. Throws InputError (degenerate or non-finite input)
// or DomainError (a result outside the range of double), as hinge::reference::theta_derivatives_rounded.
RoundedTheta hinge_derivatives_rounded(const ScalarType& type, const std::array<double, 12>& x);

}  // namespace hinge::fast
