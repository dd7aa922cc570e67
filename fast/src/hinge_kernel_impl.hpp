// fast/src/hinge_kernel_impl.hpp: the definitions of hinge/fast/hinge_kernel.hpp's templates, for the
// explicit instantiations (instantiate_*.cpp).
#pragma once

#include <stdexcept>

#include "double_kernel.hpp"
#include "generic_kernel.hpp"
#include "hinge/core/fp_environment.hpp"

namespace hinge::fast {

template <class Scalar>
HingeDerivatives<Scalar> hinge_derivatives(const std::array<double, 12>& x, bool want_hessian) {
  check_fp_environment();  // the exact steps need rounding to nearest and subnormals
  HingeDerivatives<Scalar> out;
  if constexpr (std::is_same_v<Scalar, double>) detail::hinge_kernel_double(x, want_hessian, out);
  else detail::hinge_kernel(x, want_hessian, out);
  return out;
}

template <class Scalar>
void hinge_derivatives(std::span<const std::array<double, 12>> x, std::span<HingeDerivatives<Scalar>> out,
                       bool want_hessian) {
  if (x.size() != out.size()) throw std::invalid_argument("hinge_derivatives: x and out differ in size");
  check_fp_environment();
  if constexpr (std::is_same_v<Scalar, double>)
    detail::hinge_kernel_double(x.data(), x.size(), want_hessian, out.data());
  else
    for (std::size_t i = 0; i < x.size(); ++i) detail::hinge_kernel(x[i], want_hessian, out[i]);
}

}  // namespace hinge::fast

#define HINGE_FAST_HINGE_INSTANTIATE(S)                                                                               \
  template ::hinge::fast::HingeDerivatives<S> hinge::fast::hinge_derivatives<S>(const std::array<double, 12>&, bool); \
  template void hinge::fast::hinge_derivatives<S>(std::span<const std::array<double, 12>>,                            \
                                                  std::span<::hinge::fast::HingeDerivatives<S>>, bool);
