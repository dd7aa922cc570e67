// The double per-hinge kernel (hinge/fast/hinge_kernel.hpp, isa.hpp) across eight lanes (hinge_kernel_lanes.hpp),
// compiled three times: for x86-64-v4 (AVX-512: one register per eight lanes), x86-64-v3 (AVX2 and a
// hardware fused multiply-add: two registers) and the baseline x86-64 (no FMA: the fused multiply-add
// emulated exactly in SSE2, lanes.hpp's fused_without_fma, and exact products by Dekker's). The choice is
// made once, at the first call; the results are the same bits either way (lane-by-lane IEEE operations,
// -ffp-contract=off, and the fused multiply-add correctly rounded on all three). The vector work makes no
// call (no libm fma either); its
// outcome is completed here (exact decisions, atan2, errors), in code common to the three. Many hinges
// in one call go two at a time where the processor has AVX-512 (pair_v4), each completed as if alone.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include "dispatch.hpp"
#include "double_kernel.hpp"
#include "hinge/fast/faithful.hpp"
#include "hinge/fast/isa.hpp"
#include "hinge_kernel_lanes.hpp"

namespace hinge::fast::detail {
namespace {

using Kernel = void (*)(const std::array<double, 12>* const*, bool, const Destination*, LanesOutcome*);

Destination destination(HingeDerivatives<double>& d) { return {d.grad.data(), d.hess.data()}; }

HINGE_FAST_TARGET_V4 void kernel_v4(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                    LanesOutcome* o) {
  lanes_kernel<Zmm8, false>(x, h, out, o);
}
HINGE_FAST_TARGET_V4 void rescaled_v4(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                      LanesOutcome* o) {
  lanes_kernel<Zmm8, true>(x, h, out, o);
}
HINGE_FAST_TARGET_V4 void pair_v4(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                  LanesOutcome* o) {
  lanes_kernel<Zmm8, false, 2>(x, h, out, o);
}
HINGE_FAST_TARGET_V3 void kernel_v3(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                    LanesOutcome* o) {
  lanes_kernel<Ymm8, false>(x, h, out, o);
}
HINGE_FAST_TARGET_V3 void rescaled_v3(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                      LanesOutcome* o) {
  lanes_kernel<Ymm8, true>(x, h, out, o);
}
HINGE_FAST_TARGET_V4 void faithful_v4(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                      LanesOutcome* o) {
  lanes_kernel<Zmm8, false, 1, true>(x, h, out, o);
}
HINGE_FAST_TARGET_V4 void faithful_rescaled_v4(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                               LanesOutcome* o) {
  lanes_kernel<Zmm8, true, 1, true>(x, h, out, o);
}
HINGE_FAST_TARGET_V3 void faithful_v3(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                      LanesOutcome* o) {
  lanes_kernel<Ymm8, false, 1, true>(x, h, out, o);
}
HINGE_FAST_TARGET_V3 void faithful_rescaled_v3(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                               LanesOutcome* o) {
  lanes_kernel<Ymm8, true, 1, true>(x, h, out, o);
}
void faithful_baseline(const std::array<double, 12>* const* x, bool h, const Destination* out, LanesOutcome* o) {
  lanes_kernel<Sse8, false, 1, true>(x, h, out, o);
}
void faithful_rescaled_baseline(const std::array<double, 12>* const* x, bool h, const Destination* out,
                                LanesOutcome* o) {
  lanes_kernel<Sse8, true, 1, true>(x, h, out, o);
}
void kernel_baseline(const std::array<double, 12>* const* x, bool h, const Destination* out, LanesOutcome* o) {
  lanes_kernel<Sse8, false>(x, h, out, o);
}
void rescaled_baseline(const std::array<double, 12>* const* x, bool h, const Destination* out, LanesOutcome* o) {
  lanes_kernel<Sse8, true>(x, h, out, o);
}

// pair: two hinges at once (lanes.hpp, Twice), for AVX-512 only: there one hinge's lanes are one register
// of 32, and two at once take 4-8% less time per hinge than one by one (docs/performance-log.md); AVX2 and
// the baseline hold one hinge's lanes in two registers of 16 already.
// faithful, faithful_rescaled: the faithful mode (hinge/fast/faithful.hpp).
struct Kernels {
  Kernel common, rescaled, pair, faithful, faithful_rescaled;
};
constexpr Kernels kAvx512{kernel_v4, rescaled_v4, pair_v4, faithful_v4, faithful_rescaled_v4},
    kAvx2{kernel_v3, rescaled_v3, nullptr, faithful_v3, faithful_rescaled_v3},
    kBaseline{kernel_baseline, rescaled_baseline, nullptr, faithful_baseline, faithful_rescaled_baseline};

void evaluate_faithful(const Kernels& kernels, const std::array<double, 12>& x, bool want_hessian,
                       HingeDerivatives<double>& out);

// Whether the outcome `o` of the (non-faithful) vector work is the common one, which complete() finishes
// with theta alone: computed at its scale (nothing rescaled, in the fast range), both triangles certified
// nondegenerate, theta's sign decided and nonzero, and none of the rare paths below (short hinge edge,
// nearly flat or folded with a shortish one, nearly flat).
bool common_outcome(const LanesOutcome& o) {
  return o.status == LanesOutcome::computed && o.fast_range && o.exponent == 0 && o.certain_upper && o.certain_lower &&
         o.sign != kUndecided && o.sign != 0 && !o.short_hinge_edge &&
         !(o.shortish_hinge_edge && std::min(o.s_minus, o.s_plus) < 0x1p-6) && !(o.s_minus < 0x1p-40);
}
// theta from the outcome, its sign decided (copysign rather than a branch on the sign, which is data).
double theta_of(const LanesOutcome& o, int sign) {
  return std::copysign(2 * std::atan2(o.s_minus, o.s_plus), double(sign));
}

// The outcome `o` of the vector work on x (its results already in `out`), completed (`faithful`: of the
// faithful kernels).
void complete(const Kernels& kernels, const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out,
              LanesOutcome o, bool faithful = false) {
  if (!faithful && common_outcome(o)) [[likely]] {
    out.on_branch_cut = false;
    out.theta = theta_of(o, o.sign);
    out.tan_half_theta = std::copysign(o.tan_half_theta, double(o.sign));  // eq. (12)
    if (!want_hessian) out.hess.setZero();
    return;
  }
  const std::array<double, 12>* xs[1] = {&x};
  const Destination outs[1] = {destination(out)};
  if (o.status == LanesOutcome::rescale) [[unlikely]]
    (faithful ? kernels.faithful_rescaled : kernels.rescaled)(xs, want_hessian, outs, &o);
  if (o.status == LanesOutcome::not_finite) check_finite(x);  // throws, naming the coordinate
  if (o.status == LanesOutcome::zero_hinge_edge) throw_zero_hinge_edge();
  // Validity and the sign, exactly where the filters could not decide (the generic kernel's checks, in
  // the same order and with the same messages).
  const Point x0{x[0], x[1], x[2]}, x1{x[3], x[4], x[5]}, x2{x[6], x[7], x[8]}, x3{x[9], x[10], x[11]};
  if (!o.certain_upper && zero_area_exact(x0, x1, x2)) throw_zero_area(true);
  if (!o.certain_lower && zero_area_exact(x3, x2, x1)) throw_zero_area(false);
  const int sign = o.sign != kUndecided ? o.sign : hinge_orientation_exact(x0, x1, x2, x3);
  if (sign == 0) {  // coplanar: theta is 0 or pi exactly
    out.on_branch_cut = o.folded;
    out.theta = o.folded ? boost::math::constants::pi<double>() : 0.0;
    out.tan_half_theta = o.folded ? std::numeric_limits<double>::infinity() : 0.0;
  } else {
    out.on_branch_cut = false;
    out.theta = faithful ? faithful_theta(x, sign, o.exponent, o.faithful) : theta_of(o, sign);
    out.tan_half_theta = std::copysign(o.tan_half_theta, double(sign));  // eq. (12)
  }
  if (!want_hessian) out.hess.setZero();
  if (o.exponent != 0) {  // results scaled back exactly
    for (int i = 0; i < 12; ++i) out.grad[i] = std::ldexp(out.grad[i], -o.exponent);
    if (want_hessian)
      for (int i = 0; i < 144; ++i) out.hess.data()[i] = std::ldexp(out.hess.data()[i], -2 * o.exponent);
  }
  if (!o.fast_range) [[unlikely]]
    wide_range_kernel(x, want_hessian, out);  // the same checks passed above
  else if (!faithful && (o.short_hinge_edge || (o.shortish_hinge_edge && std::min(o.s_minus, o.s_plus) < 0x1p-6)))
      [[unlikely]]
    evaluate_faithful(kernels, x, want_hessian, out);  // |theta| or pi - |theta| below ~2^-6
  // Nearly flat (|theta| < 2^-40): |n - n~| is theta itself, and the double-double normals' absolute
  // error of ~2^-104 is 2^-102 / theta relative (18.7 units of 2^-53 measured at theta ~ 1e-16): theta
  // is the faithful mode's, from the exact hinge determinant (faithful_theta.hpp).
  else if (!faithful && sign != 0 && o.s_minus < 0x1p-40) [[unlikely]] {
    HingeDerivatives<double> f;
    evaluate_faithful(kernels, x, false, f);
    out.theta = f.theta;
  }
}

// The vector work of `kernels` on x, completed.
void evaluate(const Kernels& kernels, const std::array<double, 12>& x, bool want_hessian,
              HingeDerivatives<double>& out) {
  const std::array<double, 12>* xs[1] = {&x};
  const Destination outs[1] = {destination(out)};
  LanesOutcome o;
  kernels.common(xs, want_hessian, outs, &o);
  complete(kernels, x, want_hessian, out, o);
}

// Asks for the cache lines of [p, p + bytes) in the state a write needs, so that their transfers overlap
// the arithmetic that precedes the stores instead of holding the stores back. PREFETCHW as inline assembly:
// GCC treats __builtin_prefetch as free of effects and deletes a function made only of them, and emits
// PREFETCHW for it only under -mprfchw; a processor without the instruction runs it as a no-op.
void prefetch_for_writing(const void* p, std::size_t bytes) {
  const char* c = static_cast<const char*>(p);
  for (std::size_t i = 0; i < bytes; i += 64) asm volatile("prefetchw %0" : : "m"(c[i]));
  asm volatile("prefetchw %0" : : "m"(c[bytes - 1]));
}

// The same, writing grad theta and Hess theta straight into the caller's arrays where the outcome is the
// common one (theta's sign decided by the filter, nothing rescaled, no rare path); elsewhere completed in a
// HingeDerivatives, copied. Hess theta is symmetric bit for bit (each block stored with its
// mirror), so its columns are its rows.
void evaluate_into(const Kernels& kernels, const std::array<double, 12>& x, double& theta, double* grad, double* hess) {
  prefetch_for_writing(hess, 144 * sizeof(double));
  prefetch_for_writing(grad, 12 * sizeof(double));
  // And the next hinge's slots, where a caller writes hinges in order into arrays (the C interface's
  // usual caller: one hinge a call, slot i of each array): a prefetch never faults, and where the guess
  // is wrong it costs only its own bandwidth.
  prefetch_for_writing(hess + 144, 144 * sizeof(double));
  prefetch_for_writing(grad + 12, 12 * sizeof(double));
  const std::array<double, 12>* xs[1] = {&x};
  const Destination outs[1] = {{grad, hess}};
  LanesOutcome o;
  kernels.common(xs, true, outs, &o);
  if (common_outcome(o)) [[likely]] {
    theta = theta_of(o, o.sign);
    return;
  }
  HingeDerivatives<double> d;  // completed from the same outcome: the vector work is not done twice
  std::copy(grad, grad + 12, d.grad.data());
  std::copy(hess, hess + 144, d.hess.data());
  complete(kernels, x, true, d, o);
  theta = d.theta;
  std::copy(d.grad.data(), d.grad.data() + 12, grad);
  std::copy(d.hess.data(), d.hess.data() + 144, hess);
}

// The faithful mode (hinge/fast/faithful.hpp) of `kernels` on x, completed.
void evaluate_faithful(const Kernels& kernels, const std::array<double, 12>& x, bool want_hessian,
                       HingeDerivatives<double>& out) {
  const std::array<double, 12>* xs[1] = {&x};
  const Destination outs[1] = {destination(out)};
  LanesOutcome o;
  kernels.faithful(xs, want_hessian, outs, &o);
  complete(kernels, x, want_hessian, out, o, true);
}

// Hinges [0, count) of x into out, two at a time where `kernels` can (then out[i] and out[i + 1] are
// completed in order: an error names the first failing hinge, as one by one).
void evaluate_all(const Kernels& kernels, const std::array<double, 12>* x, std::size_t count, bool want_hessian,
                  HingeDerivatives<double>* out) {
  std::size_t i = 0;
  if (kernels.pair)
    for (; i + 2 <= count; i += 2) {
      if (i + 4 <= count) prefetch_for_writing(&out[i + 2], 2 * sizeof(HingeDerivatives<double>));  // a pair ahead
      const std::array<double, 12>* xs[2] = {&x[i], &x[i + 1]};
      const Destination outs[2] = {destination(out[i]), destination(out[i + 1])};
      LanesOutcome o[2];
      kernels.pair(xs, want_hessian, outs, o);
      for (int h = 0; h < 2; ++h) {
        if (o[h].status == LanesOutcome::alone) evaluate(kernels, x[i + h], want_hessian, out[i + h]);
        else complete(kernels, x[i + h], want_hessian, out[i + h], o[h]);
      }
    }
  for (; i < count; ++i) {
    prefetch_for_writing(&out[i], sizeof(HingeDerivatives<double>));
    evaluate(kernels, x[i], want_hessian, out[i]);
  }
}

const Kernels& kernels_for(Isa isa) { return isa == Isa::avx512 ? kAvx512 : isa == Isa::avx2 ? kAvx2 : kBaseline; }

const Kernels& best_kernels() {
  static const Kernels& kernels = kernels_for(active_isa());
  return kernels;
}

}  // namespace

void hinge_kernel_double(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out) {
  evaluate(best_kernels(), x, want_hessian, out);
}

void hinge_kernel_double(const std::array<double, 12>* x, std::size_t count, bool want_hessian,
                         HingeDerivatives<double>* out) {
  evaluate_all(best_kernels(), x, count, want_hessian, out);
}

void hinge_kernel_faithful(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out) {
  evaluate_faithful(best_kernels(), x, want_hessian, out);
}

void hinge_kernel_into(const std::array<double, 12>& x, double& theta, double* grad, double* hess) {
  evaluate_into(best_kernels(), x, theta, grad, hess);
}

}  // namespace hinge::fast::detail

namespace hinge::fast {

std::string_view isa_name(Isa isa) {
  switch (isa) {
    case Isa::baseline: return "baseline";
    case Isa::avx2: return "avx2";
    case Isa::avx512: return "avx512";
  }
  return "?";
}

bool isa_available(Isa isa) {
  switch (isa) {
    case Isa::baseline: return true;
    case Isa::avx2: return detail::has_x86_64_v3();
    case Isa::avx512: return detail::has_x86_64_v4();
  }
  return false;
}

Isa active_isa() {
  static const Isa isa = [] {
    const char* value = std::getenv("HINGE_ISA");
    if (!value || !*value)
      return isa_available(Isa::avx512) ? Isa::avx512 : isa_available(Isa::avx2) ? Isa::avx2 : Isa::baseline;
    const std::string name = value;
    for (Isa candidate : {Isa::avx512, Isa::avx2, Isa::baseline})
      if (name == isa_name(candidate)) {
        if (!isa_available(candidate))
          throw std::invalid_argument("HINGE_ISA=" + name + ": this processor lacks " + name +
                                      " (x86-64-v4: AVX-512; x86-64-v3: AVX2, FMA, BMI2)");
        return candidate;
      }
    throw std::invalid_argument("HINGE_ISA=" + name + ": expected avx512, avx2 or baseline");
  }();
  return isa;
}

bool hinge_derivatives(Isa isa, const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out) {
  if (!isa_available(isa)) return false;
  detail::evaluate(detail::kernels_for(isa), x, want_hessian, out);
  return true;
}

void hinge_derivatives_into(const std::array<double, 12>& x, double& theta, double* grad, double* hess) {
  detail::hinge_kernel_into(x, theta, grad, hess);
}

bool faithful_hinge_derivatives(Isa isa, const std::array<double, 12>& x, bool want_hessian,
                                HingeDerivatives<double>& out) {
  if (!isa_available(isa)) return false;
  detail::evaluate_faithful(detail::kernels_for(isa), x, want_hessian, out);
  return true;
}

}  // namespace hinge::fast
