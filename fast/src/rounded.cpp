// hinge::fast's per-hinge kernel in a run-time scalar type, rounded to double (hinge/fast/rounded.hpp). The templates
// are instantiated elsewhere (instantiate_*.cpp); this unit only converts.
#include "hinge/fast/rounded.hpp"

#include <cmath>
#include <string>

#include "hinge/core/errors.hpp"
#include "hinge/fast/hinge_kernel.hpp"

namespace hinge::fast {
namespace {

template <class Scalar>
RoundedTheta theta_in(const std::array<double, 12>& x) {
  const HingeDerivatives<Scalar> d = hinge_derivatives<Scalar>(x, true);
  return round_theta(d.theta, d.grad, d.hess);
}

}  // namespace

RoundedTheta hinge_derivatives_rounded(const ScalarType& type, const std::array<double, 12>& x) {
  return visit_scalar_type(type, [&]<class Scalar>() { return theta_in<Scalar>(x); });
}

}  // namespace hinge::fast
