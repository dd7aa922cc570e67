// What both baselines do around their arithmetic: the contract's exact validity checks before it, and
// theta's branch cut after it.
#pragma once

#include <array>

#include "hinge/reference/hinge_checks.hpp"
#include "hinge/reference/scalar.hpp"

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

// atan2(-0, x < 0) is -pi; the contract's branch cut is +pi (the same angle).
template <HingeScalar Scalar>
Scalar on_branch(const Scalar& theta) {
  const Scalar pi = pi_of<Scalar>();
  return theta == -pi ? pi : theta;
}

}  // namespace hinge::baselines::detail
