// What both baselines do around their arithmetic: the contract's exact validity checks before it, and
// theta's branch cut after it.
#pragma once

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <optional>

#include "hinge/baselines/derivatives.hpp"
#include "hinge/core/hinge_checks.hpp"
#include "hinge/core/scalar.hpp"

namespace hinge::baselines::detail {

// The 12 coordinates in Scalar (float rounds them, every other type holds them exactly), after the
// contract's checks (hinge::InputError for a non-finite or degenerate hinge).
template <HingeScalar Scalar>
std::array<Scalar, 12> checked_coordinates(const std::array<double, 12>& x) {
  check_hinge(x);
  std::array<Scalar, 12> s;
  for (int i = 0; i < 12; ++i) s[i] = from_double<Scalar>(x[i]);
  return s;
}

// The derivatives a baseline fills: gradient and Hessian zero until written (and where not asked for).
template <HingeScalar Scalar>
Derivatives<Scalar> zero_derivatives() {
  Derivatives<Scalar> d;
  d.grad.setZero();
  d.hess.setZero();
  return d;
}

// atan2(-0, x < 0) is -pi; the contract's branch cut is +pi (the same angle).
template <HingeScalar Scalar>
Scalar on_branch(const Scalar& theta) {
  const Scalar pi = pi_of<Scalar>();
  return theta == -pi ? pi : theta;
}

// QD's atan2 (libqd 2.3) crashes on a NaN argument, prints an error for an infinity or two zeros, and
// squares its arguments (overflowing beyond 2^511, underflowing below 2^-537); the baselines reach all of
// these where their intermediates grow or shrink (they do not rescale). atan2 is invariant under scaling
// both arguments: this is the exponent e such that 2^-e brings the larger one to [1, 2), which the
// callers apply exactly before QD's atan2, or nothing where atan2 is undefined (the result is then NaN).
template <class S>
std::optional<int> qd_atan2_exponent(const S& y, const S& x) {
  if (isnan(y) || isnan(x) || isinf(y) || isinf(x) || (y == 0 && x == 0)) return std::nullopt;
  return std::max(y == 0 ? INT_MIN : std::ilogb(to_double(y)), x == 0 ? INT_MIN : std::ilogb(to_double(x)));
}

}  // namespace hinge::baselines::detail
