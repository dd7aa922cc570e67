// hinge/baselines/autodiff.hpp: theta and its derivatives by Eigen's AutoDiff module (unsupported/Eigen/
// AutoDiff): forward mode on the atan2 definition (derivatives.hpp), first order with
// AutoDiffScalar<Matrix<Scalar, 12, 1>> for the gradient, second order by nesting it,
// AutoDiffScalar<Matrix<AutoDiffScalar<Matrix<Scalar, 12, 1>>, 12, 1>>, for the Hessian: what a user
// writes first. The `autodiff` method of `hinge eval` and `hinge study`.
#pragma once

#include <array>

#include "hinge/baselines/derivatives.hpp"
#include "hinge/core/scalar.hpp"

namespace hinge::baselines {

// theta and, as `outputs` asks, grad theta and Hess theta of the hinge x (x0.x, ..., x3.z), in Scalar.
// Throws hinge::InputError for a non-finite or degenerate hinge (the contract's exact checks,
// hinge/core/hinge_checks.hpp); otherwise returns whatever the arithmetic gives, NaN and infinity
// included (no rescaling: extreme scales overflow or underflow).
template <HingeScalar Scalar>
Derivatives<Scalar> autodiff_derivatives(const std::array<double, 12>& x, Outputs outputs = Outputs::hessian);

#define HINGE_AUTODIFF_EXTERN(S) \
  extern template Derivatives<S> autodiff_derivatives<S>(const std::array<double, 12>&, Outputs);
HINGE_FOR_EACH_SCALAR(HINGE_AUTODIFF_EXTERN)
#undef HINGE_AUTODIFF_EXTERN

}  // namespace hinge::baselines
