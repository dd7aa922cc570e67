// The condition numbers of the tolerance policy (hinge/oracle/conditioning.hpp), from certified and exact
// values: the same bits on every platform (the project compiles without contraction).
#include "hinge/oracle/conditioning.hpp"

#include <cmath>

#include "hinge_intervals.hpp"
#include "interval.hpp"

namespace hinge::oracle {
namespace {

using detail::Interval;
using detail::Real;

// The longest of the five edge vectors, exactly squared in integer units, then rounded: L.
double longest_edge(const ScaledHinge& s, Int& longest_squared) {
  static constexpr int ends[5][2] = {{2, 1}, {0, 2}, {1, 0}, {3, 2}, {1, 3}};
  longest_squared = 0;
  for (const auto& e : ends) {
    Int d = 0;
    for (int c = 0; c < 3; ++c) {
      const Int t = s.X[3 * e[0] + c] - s.X[3 * e[1] + c];
      d += t * t;
    }
    if (d > longest_squared) longest_squared = d;
  }
  Real L(128);
  mpfr_set_z(L.get(), longest_squared.get_mpz_t(), MPFR_RNDN);
  mpfr_sqrt(L.get(), L.get(), MPFR_RNDN);
  mpfr_mul_2si(L.get(), L.get(), -s.F, MPFR_RNDN);
  return mpfr_get_d(L.get(), MPFR_RNDN);
}

// L ||d Hess theta / dx||_F: central differences of the exact Hessian, step one unit of the refined
// integers (at most 2^-100 L), evaluated at 320 bits. The truncation error is relatively
// O((step / h_min)^2), far below what a condition number needs.
double third_derivative_scale(const ScaledHinge& s, const Int& longest_squared, double L) {
  const std::size_t length_bits = (mpz_sizeinbase(longest_squared.get_mpz_t(), 2) + 1) / 2;
  const unsigned long extra = length_bits >= 100 ? 0 : 100 - length_bits;
  const ScaledHinge refined = refine(s, extra);
  detail::WorkingPrecision precision(320);
  Real sum(320), term(320);
  mpfr_set_ui(sum.get(), 0, MPFR_RNDN);
  for (int j = 0; j < 12; ++j) {
    ScaledHinge plus = refined, minus = refined;
    plus.X[j] += 1;
    minus.X[j] -= 1;
    const ExactHinge ep = exact_hinge(plus, true), em = exact_hinge(minus, true);
    const Interval lp = sqrt(Interval(ep.s)), lm = sqrt(Interval(em.s));
    for (int k = 0; k < 144; ++k) {
      const Interval d =
          detail::quotient(ep.h[k], ep.h_den, lp, 2 * ep.F) - detail::quotient(em.h[k], em.h_den, lm, 2 * em.F);
      mpfi_mid(term.get(), d.get());
      mpfr_mul_2si(term.get(), term.get(), refined.F - 1, MPFR_RNDN);  // / (2 step), step = 2^-F
      mpfr_sqr(term.get(), term.get(), MPFR_RNDN);
      mpfr_add(sum.get(), sum.get(), term.get(), MPFR_RNDN);
    }
  }
  mpfr_sqrt(sum.get(), sum.get(), MPFR_RNDN);
  mpfr_mul_d(sum.get(), sum.get(), L, MPFR_RNDN);
  return mpfr_get_d(sum.get(), MPFR_RNDN);
}

}  // namespace

double scaled_norm(const double* v, std::size_t n) {
  double largest = 0;
  for (std::size_t i = 0; i < n && !std::isnan(largest); ++i)
    if (!(std::fabs(v[i]) <= largest)) largest = std::isnan(v[i]) ? v[i] : std::fabs(v[i]);
  if (largest == 0 || !std::isfinite(largest)) return largest;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = v[i] / largest;
    sum += s * s;
  }
  return largest * std::sqrt(sum);
}

ConditionedTheta certified_with_conditioning(const std::array<double, 12>& x, const Options& options) {
  ConditionedTheta e;
  const ScaledHinge s = scale_exactly(x);
  const ExactHinge exact = exact_hinge(s, true);
  Options binary64 = options;
  binary64.binary32 = false;
  e.values = certify(exact, binary64);
  Int longest_squared;
  Conditioning& k = e.conditioning;
  k.length = longest_edge(s, longest_squared);
  k.scale[0] = k.length * scaled_norm(e.values.grad.data(), 12);   // J_theta = grad theta
  k.scale[1] = k.length * scaled_norm(e.values.hess.data(), 144);  // J_grad = Hess theta
  k.scale[2] = third_derivative_scale(s, longest_squared, k.length);
  const double sizes[3] = {scaled_norm(&e.values.theta, 1), scaled_norm(e.values.grad.data(), 12),
                           scaled_norm(e.values.hess.data(), 144)};
  for (int g = 0; g < 3; ++g) k.kappa[g] = sizes[g] == 0 ? 1.0 : k.scale[g] / sizes[g];
  if (options.binary32) e.values = certify(exact, options);
  return e;
}

}  // namespace hinge::oracle
