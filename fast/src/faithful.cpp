// The faithful mode's entry points (hinge/fast/faithful.hpp); the kernel is hinge_kernel_double.cpp's.
#include "hinge/fast/faithful.hpp"

#include "double_kernel.hpp"

namespace hinge::fast {

HingeDerivatives<double> faithful_hinge_derivatives(const std::array<double, 12>& x, bool want_hessian) {
  HingeDerivatives<double> out;
  detail::hinge_kernel_faithful(x, want_hessian, out);
  return out;
}

RoundedTheta faithful_derivatives_rounded(const std::array<double, 12>& x) {
  const HingeDerivatives<double> d = faithful_hinge_derivatives(x, true);
  return round_theta(d.theta, d.grad, d.hess);
}

}  // namespace hinge::fast
