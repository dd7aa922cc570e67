// One row of the study (a method in a scalar type): its times and its errors. The template is
// instantiated per scalar family (rows_*.cpp); the methods themselves are instantiated in their own
// libraries, so these units compile only the glue.
#pragma once

#include <mpfr.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <vector>

#include "hinge/baselines/derivatives.hpp"
#include "hinge/conformance/grading.hpp"
#include "hinge/fast/hinge_kernel.hpp"
#include "hinge/reference/rounded.hpp"
#include "prepared.hpp"

namespace hinge::study::detail {

// theta, grad theta and Hess theta of one hinge in Scalar (the baselines' type, for every method).
template <class Scalar>
using Outputs = baselines::Derivatives<Scalar>;

template <class Scalar>
Outputs<Scalar> evaluate(methods::Method method, const std::array<double, 12>& x) {
  using methods::Method;
  switch (method) {
    case Method::reference: {
      const auto d = reference::theta_derivatives<Scalar>(x, true);
      return {d.angle.theta, d.grad, d.hess};
    }
    case Method::fast: {
      const auto d = fast::hinge_derivatives<Scalar>(x, true);
      return {d.theta, d.grad, d.hess};
    }
    case Method::autodiff: {
      const auto d = baselines::autodiff_derivatives<Scalar>(x, baselines::Outputs::hessian);
      return {d.theta, d.grad, d.hess};
    }
    case Method::symbolic: {
      const auto d = baselines::symbolic_derivatives<Scalar>(x, baselines::Outputs::hessian);
      return {d.theta, d.grad, d.hess};
    }
  }
  throw std::invalid_argument("study: unknown method");
}

// One call of `method` for output group g (0 theta, 1 theta and gradient, 2 all three), returning theta
// (for the timing loop to consume). The reference's theta alone is its stencil and bend angle; fast
// computes the gradient with theta, so its group 0 is its group 1.
template <class Scalar>
Scalar call(methods::Method method, int g, const std::array<double, 12>& x) {
  using methods::Method;
  const baselines::Outputs level = g == 0   ? baselines::Outputs::theta
                                   : g == 1 ? baselines::Outputs::gradient
                                            : baselines::Outputs::hessian;
  switch (method) {
    case Method::reference:
      if (g == 0) {
        const reference::PreparedHinge<Scalar> h = reference::prepare_hinge<Scalar>(x);
        return reference::bend_angle(h.stencil, h.sign).theta;
      }
      return reference::theta_derivatives<Scalar>(x, g == 2).angle.theta;
    case Method::fast: return fast::hinge_derivatives<Scalar>(x, g == 2).theta;
    case Method::autodiff: return baselines::autodiff_derivatives<Scalar>(x, level).theta;
    case Method::symbolic: return baselines::symbolic_derivatives<Scalar>(x, level).theta;
  }
  throw std::invalid_argument("study: unknown method");
}

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// v into `out` (whose precision is the wide reference's, at least twice Scalar's: exact).
template <class Scalar>
void set_mpfr_t(mpfr_ptr out, const Scalar& v) {
  if constexpr (std::same_as<Scalar, mpfr>) {
    mpfr_set(out, v.backend().data(), MPFR_RNDN);
  } else {
    const mpfr m = to_mpfr(v);  // at the current precision, the wide reference's
    mpfr_set(out, m.backend().data(), MPFR_RNDN);
  }
}

// ||computed - wide|| / ||wide|| over n values in units of u (relative to `scale` where the wide values
// are all zero), in MPFR at `bits`.
template <class Scalar, class Computed, class Wide>
double own_error(std::size_t n, Computed computed, Wide wide, unsigned bits, double u, double scale) {
  mpfr_t d, s, a, b;
  mpfr_inits2(static_cast<mpfr_prec_t>(bits), d, s, a, b, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_ui(d, 0, MPFR_RNDN);
  mpfr_set_ui(s, 0, MPFR_RNDN);
  for (std::size_t i = 0; i < n; ++i) {
    set_mpfr_t<Scalar>(a, computed(i));
    set_mpfr_t<mpfr>(b, wide(i));
    mpfr_fma(s, b, b, s, MPFR_RNDN);
    mpfr_sub(a, a, b, MPFR_RNDN);
    mpfr_fma(d, a, a, d, MPFR_RNDN);
  }
  mpfr_sqrt(d, d, MPFR_RNDN);
  mpfr_sqrt(s, s, MPFR_RNDN);
  const double difference = mpfr_get_d(d, MPFR_RNDN), size = mpfr_get_d(s, MPFR_RNDN);
  mpfr_clears(d, s, a, b, static_cast<mpfr_ptr>(nullptr));
  if (difference == 0) return 0;
  const double normalizer = size > 0 ? size : scale;
  return normalizer > 0 && std::isfinite(difference) ? difference / normalizer / u : INFINITY;
}

// Median and maximum of each group's errors.
GroupErrors statistics(std::array<std::vector<double>, 3>& errors);

// Whether every output is finite.
template <class Scalar>
bool finite(const Outputs<Scalar>& r) {
  using std::isfinite;
  bool ok = isfinite(r.theta);
  for (const auto& g : r.grad) ok = ok && isfinite(g);
  for (const auto& h : r.hess.reshaped()) ok = ok && isfinite(h);
  return ok;
}

// The row of `method` in Scalar (mpfr at scalar.mpfr_bits): errors on the prepared hinges in their
// interleaved order until 70% of `budget` seconds are spent, then times on the timing hinges.
template <class Scalar>
Row measure_row(methods::Method method, const ScalarType& scalar, const Prepared& p, double budget, bool quick) {
  Row row;
  row.method = method;
  row.scalar = scalar;
  const auto start = Clock::now();
  const auto set_precision = [&] {
    if constexpr (std::same_as<Scalar, mpfr>) set_mpfr_bits(scalar.mpfr_bits);
  };
  set_precision();
  int precision = std::numeric_limits<Scalar>::digits;  // QD: 104 and 209 (its own count)
  if constexpr (std::same_as<Scalar, mpfr>) precision = static_cast<int>(mpfr_bits());
  const bool wider = precision > 53;
  const auto wide_bits = static_cast<unsigned>(std::max(2 * precision + 32, precision + 100));
  const double u_own = to_double(unit_roundoff<Scalar>());

  std::map<std::string, std::array<std::vector<double>, 3>> rounded_errors, own_errors;
  for (const std::size_t i : p.order) {
    if (row.hinges > 0 && seconds_since(start) > 0.7 * budget) break;
    ++row.hinges;
    const StudyHinge& h = p.hinges[i];
    std::optional<Outputs<Scalar>> r;
    try {
      r = evaluate<Scalar>(method, h.x);
    } catch (const InputError&) {
      ++row.failed;
      continue;
    } catch (const DomainError&) {
      ++row.failed;
      continue;
    }
    RoundedTheta rounded;
    try {
      if (!finite(*r)) throw DomainError("not finite");
      rounded = round_theta(r->theta, r->grad, r->hess);
    } catch (const DomainError&) {  // a NaN, an infinity, or a value outside the range of double
      ++row.nonfinite;
      continue;
    }
    const oracle::CertifiedTheta& c = p.certified[i];
    auto& e = rounded_errors[h.category];
    namespace conf = conformance;
    e[0].push_back(conf::normwise_error(&rounded.theta, &c.theta, 1, p.scale[i][0]));
    e[1].push_back(conf::normwise_error(rounded.grad.data(), c.grad.data(), 12, p.scale[i][1]));
    e[2].push_back(conf::normwise_error(rounded.hess.data(), c.hess.data(), 144, p.scale[i][2]));
    row.hess_errors.push_back(e[2].back());
    if (wider) {
      const auto& w = p.wide(i, wide_bits);  // sets the precision to wide_bits: conversions below are exact
      if (w) {
        auto& o = own_errors[h.category];
        o[0].push_back(own_error<Scalar>(
            1, [&](std::size_t) { return r->theta; }, [&](std::size_t) { return w->angle.theta; }, wide_bits, u_own,
            p.scale[i][0]));
        o[1].push_back(own_error<Scalar>(
            12, [&](std::size_t k) { return r->grad[k]; }, [&](std::size_t k) { return w->grad[k]; }, wide_bits, u_own,
            p.scale[i][1]));
        o[2].push_back(own_error<Scalar>(
            144, [&](std::size_t k) { return r->hess.reshaped()[k]; },
            [&](std::size_t k) { return w->hess.reshaped()[k]; }, wide_bits, u_own, p.scale[i][2]));
      }
      set_precision();
    }
  }
  for (auto& [category, e] : rounded_errors) row.error_u[category] = statistics(e);
  for (auto& [category, e] : own_errors) row.error_own[category] = statistics(e);

  // Times: passes over the timing hinges, one group a pass, the groups in turn; at least 3 passes of each
  // (quick) or 5, and 0.02 s (quick) or 0.2 s of each group, within the budget.
  const std::size_t min_passes = quick ? 3 : 5;
  const double min_seconds = quick ? 0.02 : 0.2;
  std::vector<std::array<double, 12>> timed;
  const auto check_start = Clock::now();
  for (const auto& x : p.timing) {  // the hinges this method evaluates (a first pass, which also warms up)
    try {
      (void)call<Scalar>(method, 2, x);
      timed.push_back(x);
    } catch (const std::exception&) {
    }
    if (seconds_since(check_start) > 0.1 * budget) break;  // slow rows: time fewer hinges
  }
  if (!timed.empty()) {  // as many hinges as three passes of each group can take within the budget
    const double per_hinge = seconds_since(check_start) / static_cast<double>(timed.size());
    const double left = std::max(0.0, budget - seconds_since(start));
    const auto fit = static_cast<std::size_t>(left / (9 * per_hinge));
    timed.resize(std::clamp<std::size_t>(fit, std::min<std::size_t>(16, timed.size()), timed.size()));
  }
  if (!timed.empty()) {
    std::array<std::vector<double>, 3> per_hinge;
    std::array<double, 3> spent{};
    volatile double sink = 0;
    for (std::size_t pass = 0;; ++pass) {
      bool enough = pass >= min_passes;
      for (int g = 0; g < 3; ++g) enough = enough && spent[g] >= min_seconds;
      if (enough || (pass >= 1 && seconds_since(start) > budget)) break;
      for (int g = 0; g < 3; ++g) {
        const auto t0 = Clock::now();
        double acc = 0;
        for (const auto& x : timed) acc += to_double(call<Scalar>(method, g, x));
        const double s = seconds_since(t0);
        sink = sink + acc;
        spent[g] += s;
        per_hinge[g].push_back(1e9 * s / static_cast<double>(timed.size()));
      }
    }
    for (int g = 0; g < 3; ++g) {
      auto& v = per_hinge[g];
      std::sort(v.begin(), v.end());
      row.ns_per_hinge[g] = v[v.size() / 2];
    }
  }
  row.seconds = seconds_since(start);
  return row;
}

#define HINGE_STUDY_ROW_EXTERN(S) \
  extern template Row measure_row<S>(methods::Method, const ScalarType&, const Prepared&, double, bool);
HINGE_FOR_EACH_SCALAR(HINGE_STUDY_ROW_EXTERN)
#undef HINGE_STUDY_ROW_EXTERN

}  // namespace hinge::study::detail

// For the generated instantiation units (hinge_scalar_units in study/CMakeLists.txt), one per scalar family.
#define HINGE_STUDY_ROW_INSTANTIATE(S)                             \
  template hinge::study::Row hinge::study::detail::measure_row<S>( \
      hinge::methods::Method, const hinge::ScalarType&, const hinge::study::detail::Prepared&, double, bool);
