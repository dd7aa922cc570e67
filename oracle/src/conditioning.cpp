// The condition numbers of the tolerance policy (hinge/oracle/conditioning.hpp), from certified and exact
// values: the same bits on every platform (the project compiles without contraction).
#include "hinge/oracle/conditioning.hpp"

#include <algorithm>
#include <cmath>

#include "hinge_energy.hpp"
#include "hinge_intervals.hpp"
#include "interval.hpp"
#include "quadratic_enclosure.hpp"

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

// Each of a hinge's 24 coordinates (X's, then R's) perturbed by +-1 unit of the refined integers: the
// central differences of psi, its gradient and Hessian, summed in squares per output group.
class EnergyDifferences {
 public:
  EnergyDifferences(const ScaledHinge& x, const ScaledHinge& rest, const EnergyParameters& p, bool gauss_newton,
                    bool quadratic = false)
      : x_(x), rest_(rest), p_(p), gauss_newton_(gauss_newton), quadratic_(quadratic) {}

  // sum over the coordinates of side `which` (0: X, 1: R), refined by `extra` bits, of the squared
  // derivatives of each output group, added to `sums`.
  void add(int which, unsigned long extra, std::array<Real, 3>& sums) const {
    const ScaledHinge refined = refine(which == 0 ? x_ : rest_, extra);
    Real term(320);
    for (int j = 0; j < 12; ++j) {
      ScaledHinge plus = refined, minus = refined;
      plus.X[j] += 1;
      minus.X[j] -= 1;
      const detail::HingeEnergy ep = evaluate(which, plus), em = evaluate(which, minus);
      const auto add_square = [&](const Interval& a, const Interval& b, Real& sum) {
        const Interval d = a - b;
        mpfi_mid(term.get(), d.get());
        mpfr_mul_2si(term.get(), term.get(), refined.F - 1, MPFR_RNDN);  // / (2 step), step = 2^-F
        mpfr_sqr(term.get(), term.get(), MPFR_RNDN);
        mpfr_add(sum.get(), sum.get(), term.get(), MPFR_RNDN);
      };
      add_square(ep.value, em.value, sums[0]);
      for (int k = 0; k < 12; ++k) add_square(ep.grad[k], em.grad[k], sums[1]);
      for (int k = 0; k < 144; ++k) add_square(ep.hess[k], em.hess[k], sums[2]);
    }
  }

 private:
  detail::HingeEnergy evaluate(int which, const ScaledHinge& perturbed) const {
    if (quadratic_) {  // quadratic.hpp: a polynomial in X with the rest hinge's cotangent weights
      const ScaledHinge& rest = which == 1 ? perturbed : rest_;
      return detail::quadratic_enclosure(which == 0 ? perturbed : x_, rest, exact_hinge(rest, false), Interval(p_.k));
    }
    const ExactHinge deformed = exact_hinge(which == 0 ? perturbed : x_, true);
    const ExactHinge rest = exact_hinge(which == 1 ? perturbed : rest_, false);
    return detail::hinge_energy(p_.model, Interval(p_.k), Interval(p_.k_d_over_dt), deformed, rest,
                                same_angle(deformed, rest), true, true, gauss_newton_);
  }

  const ScaledHinge &x_, &rest_;
  const EnergyParameters& p_;
  bool gauss_newton_, quadratic_;
};

// The refinement that makes one unit of h's integers at most 2^-100 of its longest edge.
unsigned long refinement(const Int& longest_squared) {
  const std::size_t length_bits = (mpz_sizeinbase(longest_squared.get_mpz_t(), 2) + 1) / 2;
  return length_bits >= 100 ? 0 : 100 - length_bits;
}

}  // namespace

namespace {

Conditioning conditioning_of(const std::array<double, 12>& x, const std::array<double, 12>& rest,
                             const EnergyParameters& parameters, bool gauss_newton, bool quadratic, double energy,
                             const std::array<double, 12>& grad, const std::array<double, 144>& hess) {
  const ScaledHinge sx = scale_exactly(x), sr = scale_exactly(rest);
  const ExactHinge r = exact_hinge(sr, false);
  if (!quadratic && infinite_at_pi(parameters.model) && sgn(r.Y) == 0 && sgn(r.X) < 0)
    throw_folded_rest(parameters.model);
  Int longest_x, longest_r;
  Conditioning k;
  k.length = std::max(longest_edge(sx, longest_x), longest_edge(sr, longest_r));
  detail::WorkingPrecision precision(320);
  std::array<Real, 3> sums{Real(320), Real(320), Real(320)};
  for (Real& s : sums) mpfr_set_ui(s.get(), 0, MPFR_RNDN);
  const EnergyDifferences differences(sx, sr, parameters, gauss_newton, quadratic);
  differences.add(0, refinement(longest_x), sums);
  differences.add(1, refinement(longest_r), sums);
  const double sizes[3] = {scaled_norm(&energy, 1), scaled_norm(grad.data(), 12), scaled_norm(hess.data(), 144)};
  for (int g = 0; g < 3; ++g) {
    mpfr_sqrt(sums[g].get(), sums[g].get(), MPFR_RNDN);
    mpfr_mul_d(sums[g].get(), sums[g].get(), k.length, MPFR_RNDN);
    k.scale[g] = mpfr_get_d(sums[g].get(), MPFR_RNDN);
    k.kappa[g] = sizes[g] == 0 ? 1.0 : k.scale[g] / sizes[g];
  }
  return k;
}

}  // namespace

Conditioning energy_conditioning(const std::array<double, 12>& x, const std::array<double, 12>& rest,
                                 const EnergyParameters& parameters, bool gauss_newton, double energy,
                                 const std::array<double, 12>& grad, const std::array<double, 144>& hess) {
  return conditioning_of(x, rest, parameters, gauss_newton, false, energy, grad, hess);
}

Conditioning quadratic_conditioning(const std::array<double, 12>& x, const std::array<double, 12>& rest, double k,
                                    double energy, const std::array<double, 12>& grad,
                                    const std::array<double, 144>& hess) {
  EnergyParameters parameters;
  parameters.k = k;
  return conditioning_of(x, rest, parameters, false, true, energy, grad, hess);
}

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
