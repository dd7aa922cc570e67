// fast/src/double_kernel.hpp: the double per-hinge kernel (hinge_kernel_lanes.hpp) compiled for each
// instruction set (hinge_kernel_double.cpp), as the rest of the library calls it.
#pragma once

#include <array>
#include <cstddef>

#include "hinge/fast/hinge_kernel.hpp"
#include "hinge/fast/isa.hpp"

namespace hinge::fast::detail {

// The double kernel (src/hinge_kernel_lanes.hpp), compiled for the baseline x86-64, x86-64-v3 (AVX2 and
// a hardware fused multiply-add) and x86-64-v4 (AVX-512), the best the processor has chosen at run time
// (src/hinge_kernel_double.cpp); all give the same bits.
void hinge_kernel_double(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out);
// Hinges x[0 .. count) into out[0 .. count), two at a time where the processor has AVX-512.
void hinge_kernel_double(const std::array<double, 12>* x, std::size_t count, bool want_hessian,
                         HingeDerivatives<double>* out);
// The faithful mode (hinge/fast/faithful.hpp) of the same kernel.
void hinge_kernel_faithful(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out);
// hinge_derivatives_into (hinge/fast/hinge_kernel.hpp).
void hinge_kernel_into(const std::array<double, 12>& x, double& theta, double* grad, double* hess);

}  // namespace hinge::fast::detail
