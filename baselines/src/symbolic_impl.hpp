// hinge::baselines::symbolic_derivatives (hinge/baselines/derivatives.hpp): the code SymPy generated
// (symbolic_theta.inc, from symbolic_theta.py), called per output level. Instantiated per scalar family
// (symbolic_*.cpp).
#pragma once

#include "common.hpp"
#include "hinge/baselines/derivatives.hpp"

namespace hinge::baselines {
namespace generated {
using hinge::sqrt;  // the built-in types' std:: functions; the others' are found by argument-dependent lookup

// atan2 as the generated code calls it: the scalar type's (for QD's, its arguments brought near 1 by a
// power of two first, or NaN where it is undefined: common.hpp).
template <class S>
S theta_atan2(const S& y, const S& x) {
  if constexpr (QdScalar<S>) {
    const std::optional<int> e = detail::qd_atan2_exponent(y, x);
    if (!e) return S(std::numeric_limits<double>::quiet_NaN());
    return atan2(ldexp(y, -*e), ldexp(x, -*e));
  } else {
    using std::atan2;
    return atan2(y, x);
  }
}

#include "symbolic_theta.inc"
}  // namespace generated

template <HingeScalar Scalar>
Derivatives<Scalar> symbolic_derivatives(const std::array<double, 12>& x, Outputs outputs) {
  const std::array<Scalar, 12> s = detail::checked_coordinates<Scalar>(x);
  Derivatives<Scalar> d = detail::zero_derivatives<Scalar>();
  switch (outputs) {
    case Outputs::theta: generated::symbolic_theta(s.data(), d.theta); break;
    case Outputs::gradient: generated::symbolic_theta_gradient(s.data(), d.theta, d.grad.data()); break;
    case Outputs::hessian:  // the generated code writes row-major; Eigen's matrix is column-major and symmetric here
      generated::symbolic_theta_hessian(s.data(), d.theta, d.grad.data(), d.hess.data());
      break;
  }
  d.theta = detail::on_branch(d.theta);
  return d;
}

}  // namespace hinge::baselines

#define HINGE_SYMBOLIC_INSTANTIATE(S)                                                                                \
  template hinge::baselines::Derivatives<S> hinge::baselines::symbolic_derivatives<S>(const std::array<double, 12>&, \
                                                                                      Outputs);
