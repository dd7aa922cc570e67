// The double per-hinge kernel (hinge/fast/hinge_kernel.hpp), compiled twice: for the baseline x86-64 and
// for x86-64-v3, whose hardware fused multiply-add the double-double arithmetic of exact.hpp lives on
// (the baseline calls libm's fma). The choice is made once, at the first call; the results are the same
// bits either way (-ffp-contract=off, and fma is exact on both).
#include "hinge/fast/dispatch.hpp"
#include "hinge/fast/hinge_kernel.hpp"

namespace hinge::fast::detail {
namespace {

HINGE_FAST_TARGET_V3 void kernel_v3(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out) {
  hinge_kernel<double>(x, want_hessian, out);
}
void kernel_baseline(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out) {
  hinge_kernel<double>(x, want_hessian, out);
}

}  // namespace

void hinge_kernel_double(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out) {
  static const auto kernel = has_x86_64_v3() ? kernel_v3 : kernel_baseline;
  kernel(x, want_hessian, out);
}

}  // namespace hinge::fast::detail
