// The double per-hinge kernel (hinge/fast/hinge_kernel.hpp) across eight lanes (hinge_kernel_lanes.hpp),
// compiled three times: for x86-64-v4 (AVX-512: one register per eight lanes), x86-64-v3 (AVX2 and a
// hardware fused multiply-add: two registers) and the baseline x86-64 (which calls libm's fma). The
// choice is made once, at the first call; the results are the same bits either way (lane-by-lane IEEE
// operations, -ffp-contract=off, and fma is exact on all three). The vector work makes no call; its
// outcome is completed here (exact decisions, atan2, errors), in code common to the three.
#include <cmath>
#include <limits>

#include "hinge/fast/dispatch.hpp"
#include "hinge_kernel_lanes.hpp"

namespace hinge::fast::detail {
namespace {

using Kernel = LanesOutcome (*)(const std::array<double, 12>&, bool, HingeDerivatives<double>&);

HINGE_FAST_TARGET_V4 LanesOutcome kernel_v4(const std::array<double, 12>& x, bool h, HingeDerivatives<double>& out) {
  return lanes_kernel<Zmm8, false>(x, h, out);
}
HINGE_FAST_TARGET_V4 LanesOutcome rescaled_v4(const std::array<double, 12>& x, bool h, HingeDerivatives<double>& out) {
  return lanes_kernel<Zmm8, true>(x, h, out);
}
HINGE_FAST_TARGET_V3 LanesOutcome kernel_v3(const std::array<double, 12>& x, bool h, HingeDerivatives<double>& out) {
  return lanes_kernel<Ymm8, false>(x, h, out);
}
HINGE_FAST_TARGET_V3 LanesOutcome rescaled_v3(const std::array<double, 12>& x, bool h, HingeDerivatives<double>& out) {
  return lanes_kernel<Ymm8, true>(x, h, out);
}
LanesOutcome kernel_baseline(const std::array<double, 12>& x, bool h, HingeDerivatives<double>& out) {
  return lanes_kernel<Sse8, false>(x, h, out);
}
LanesOutcome rescaled_baseline(const std::array<double, 12>& x, bool h, HingeDerivatives<double>& out) {
  return lanes_kernel<Sse8, true>(x, h, out);
}

struct Kernels {
  Kernel common, rescaled;
};
constexpr Kernels kAvx512{kernel_v4, rescaled_v4}, kAvx2{kernel_v3, rescaled_v3}, kBaseline{kernel_baseline, rescaled_baseline};

// The vector work of `kernels`, completed.
void evaluate(const Kernels& kernels, const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out) {
  LanesOutcome o = kernels.common(x, want_hessian, out);
  if (o.status == LanesOutcome::rescale) [[unlikely]] o = kernels.rescaled(x, want_hessian, out);
  if (o.status == LanesOutcome::not_finite) throw_not_finite(x);
  if (o.status == LanesOutcome::zero_hinge_edge)
    throw InputError("degenerate hinge: the hinge edge has zero length (x1 == x2)");
  // Validity and the sign, exactly where the filters could not decide (the generic kernel's checks, in
  // the same order and with the same messages).
  const Point x0{x[0], x[1], x[2]}, x1{x[3], x[4], x[5]}, x2{x[6], x[7], x[8]}, x3{x[9], x[10], x[11]};
  if (!o.certain_upper && zero_area_exact(x0, x1, x2))
    throw InputError("degenerate hinge: the upper triangle (x0, x1, x2) has zero area");
  if (!o.certain_lower && zero_area_exact(x3, x2, x1))
    throw InputError("degenerate hinge: the lower triangle (x3, x2, x1) has zero area");
  const int sign = o.sign != kUndecided ? o.sign : hinge_orientation_exact(x0, x1, x2, x3);
  if (sign == 0) {  // coplanar: theta is 0 or pi exactly
    out.on_branch_cut = o.folded;
    out.theta = o.folded ? boost::math::constants::pi<double>() : 0.0;
    out.tan_half_theta = o.folded ? std::numeric_limits<double>::infinity() : 0.0;
  } else {
    out.on_branch_cut = false;
    // (copysign rather than a branch on the sign, which is data)
    out.theta = std::copysign(2 * std::atan2(o.s_minus, o.s_plus), double(sign));
    out.tan_half_theta = std::copysign(o.tan_half_theta, double(sign));  // eq. (12)
  }
  if (!want_hessian) out.hess.setZero();
  if (o.exponent != 0) {  // results scaled back exactly
    for (int i = 0; i < 12; ++i) out.grad[i] = std::ldexp(out.grad[i], -o.exponent);
    if (want_hessian)
      for (int i = 0; i < 144; ++i) out.hess.data()[i] = std::ldexp(out.hess.data()[i], -2 * o.exponent);
  }
  if (!o.fast_range) [[unlikely]] wide_range_kernel(x, want_hessian, out);  // the same checks passed above
}

}  // namespace

void hinge_kernel_double(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out) {
  static const Kernels& kernels = has_x86_64_v4() ? kAvx512 : has_x86_64_v3() ? kAvx2 : kBaseline;
  evaluate(kernels, x, want_hessian, out);
}

bool hinge_kernel_double(KernelIsa isa, const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out) {
  switch (isa) {
    case KernelIsa::avx512:
      if (!has_x86_64_v4()) return false;
      evaluate(kAvx512, x, want_hessian, out);
      return true;
    case KernelIsa::avx2:
      if (!has_x86_64_v3()) return false;
      evaluate(kAvx2, x, want_hessian, out);
      return true;
    case KernelIsa::baseline:
      evaluate(kBaseline, x, want_hessian, out);
      return true;
  }
  return false;
}

}  // namespace hinge::fast::detail
