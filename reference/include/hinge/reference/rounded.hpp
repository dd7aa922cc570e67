// hinge/reference/rounded.hpp: the reference evaluated in a scalar type chosen at run time, every output
// rounded to the nearest double. This is what `hinge eval --method reference --scalar S`, `hinge
// oracle` and `hinge hessian --method reference` call; it keeps multiprecision templates out of tools/.
// The rounding itself: hinge/core/rounding.hpp.
#pragma once

#include <array>

#include "hinge/core/results.hpp"
#include "hinge/core/rounding.hpp"
#include "hinge/core/scalar.hpp"
#include "hinge/reference/assemble.hpp"

namespace hinge::reference {

// theta, grad theta, Hess theta of the hinge `x` in `type`, rounded to double. Throws InputError
// (degenerate or non-finite input) or DomainError (a result outside the range of double).
RoundedTheta theta_derivatives_rounded(const ScalarType& type, const std::array<double, 12>& x);

// rest_state + assemble in `type`, rounded to double. Throws as they do, and DomainError for a result
// outside the range of double.
RoundedMesh assemble_rounded(const ScalarType& type, const Mesh& deformed, const Mesh& rest, const Topology& topology,
                             const EnergyParameters& parameters, unsigned request = want_all);

}  // namespace hinge::reference
