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
#include "timing.hpp"

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

// One call of `method` in Scalar for output group g (0 theta, 1 theta and gradient, 2 all three) into slot
// i of the caller's arrays, each output rounded to double there. The reference's theta alone is its stencil
// and bend angle; fast computes the gradient with theta, so its group 0 is its group 1; fast in double
// writes straight into the arrays (hinge_derivatives_into).
template <class Scalar>
void call_into(methods::Method method, int g, const std::array<double, 12>& x, Slots& out, std::size_t i) {
  using methods::Method;
  const auto store = [&](const auto& theta, const auto& grad, const auto& hess) {
    out.theta[i] = to_double(theta);
    if (g >= 1)
      for (int k = 0; k < 12; ++k) out.grad[12 * i + k] = to_double(grad[k]);
    if (g == 2)
      for (int r = 0; r < 12; ++r)
        for (int c = 0; c < 12; ++c) out.hess[144 * i + 12 * r + c] = to_double(hess(r, c));
  };
  const baselines::Outputs level = g == 0   ? baselines::Outputs::theta
                                   : g == 1 ? baselines::Outputs::gradient
                                            : baselines::Outputs::hessian;
  switch (method) {
    case Method::reference:
      if (g == 0) {
        const reference::PreparedHinge<Scalar> h = reference::prepare_hinge<Scalar>(x);
        out.theta[i] = to_double(reference::bend_angle(h.stencil, h.sign).theta);
        return;
      } else {
        const auto d = reference::theta_derivatives<Scalar>(x, g == 2);
        store(d.angle.theta, d.grad, d.hess);
        return;
      }
    case Method::fast:
      if constexpr (std::same_as<Scalar, double>) {
        fast_into(g, x, out, i);
      } else {
        const auto d = fast::hinge_derivatives<Scalar>(x, g == 2);
        store(d.theta, d.grad, d.hess);
      }
      return;
    case Method::autodiff: {
      const auto d = baselines::autodiff_derivatives<Scalar>(x, level);
      store(d.theta, d.grad, d.hess);
      return;
    }
    case Method::symbolic: {
      const auto d = baselines::symbolic_derivatives<Scalar>(x, level);
      store(d.theta, d.grad, d.hess);
      return;
    }
  }
  throw std::invalid_argument("study: unknown method");
}

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

// The normwise errors of prepared hinge i's outputs `rounded` (theta, gradient, Hessian) against the
// certified ones into `errors`, the Hessian's also into row.hess_errors (the histogram's data).
void record_errors(Row& row, const Prepared& p, std::size_t i, const RoundedTheta& rounded,
                   std::array<std::vector<double>, 3>& errors);

// Whether every output is finite.
template <class Scalar>
bool finite(const Outputs<Scalar>& r) {
  using std::isfinite;
  bool ok = isfinite(r.theta);
  for (const auto& g : r.grad) ok = ok && isfinite(g);
  for (const auto& h : r.hess.reshaped()) ok = ok && isfinite(h);
  return ok;
}

// The errors of a row whose outputs in Scalar `evaluate(i)` gives for prepared hinge i (throwing
// InputError or DomainError where it cannot), on the prepared hinges in their interleaved order until
// `deadline` (at least one hinge): error_u per category, and error_own for types wider than double.
template <class Scalar, class Evaluate>
void measure_errors(Row& row, const ScalarType& scalar, const Prepared& p, Clock::time_point deadline,
                    Evaluate&& evaluate) {
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
    if (row.hinges > 0 && Clock::now() > deadline) break;
    ++row.hinges;
    const StudyHinge& h = p.hinges[i];
    std::optional<Outputs<Scalar>> r;
    try {
      r = evaluate(i);
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
    record_errors(row, p, i, rounded, rounded_errors[h.category]);
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
}

// The timing hinges `call(g, x, slots, i)` evaluates without an exception, within a tenth of `seconds`
// (at least one, if any).
template <class Call>
std::vector<std::array<double, 12>> timing_hinges(const Prepared& p, double seconds, Call&& call) {
  std::vector<std::array<double, 12>> timed;
  Slots slots(1);
  const auto start = Clock::now();
  for (const auto& x : p.timing) {
    try {
      call(2, x, slots, 0);
      timed.push_back(x);
    } catch (const std::exception&) {
    }
    if (!timed.empty() && seconds_since(start) > 0.1 * seconds) break;  // slow rows: time fewer hinges
  }
  return timed;
}

// The row's timer against fast in double (timing.hpp) on the timing hinges it evaluates, `call(g, x, slots,
// i)` writing into the caller's arrays (`prepare()` before each pass: mpfr's precision, a global setting);
// `groups` 1 when the three groups are one call. Its rounds spend `budget` seconds at most (after 3); none
// when it evaluates no timing hinge.
template <class Call, class Prepare>
std::optional<RowTimer> row_timer(const Row& row, const Prepared& p, double budget, bool quick, int groups, Call call,
                                  Prepare prepare) {
  prepare();
  auto timed = std::make_shared<const std::vector<std::array<double, 12>>>(timing_hinges(p, budget, call));
  if (timed->empty()) return std::nullopt;
  const std::size_t n = timed->size();
  auto row_slots = std::make_shared<Slots>(n), fast_slots = std::make_shared<Slots>(n);
  const auto row_pass = [=](int g, std::size_t begin, std::size_t count, int repeats) {
    prepare();
    return timed_pass(begin, count, n, repeats, [&](std::size_t i) { call(g, (*timed)[i], *row_slots, i); });
  };
  const auto fast_pass = [=](int g, std::size_t begin, std::size_t count, int repeats) {
    return timed_pass(begin, count, n, repeats, [&](std::size_t i) { fast_into(g, (*timed)[i], *fast_slots, i); });
  };
  const bool same = row.method == "fast" && row.scalar.kind == ScalarType::Kind::kind_double;
  return round_timer(row_pass, fast_pass, n, groups, round_policy(quick), budget, same);
}

// The row of `method` in Scalar (mpfr at scalar.mpfr_bits): errors for half the budget, and its timer for
// the other half.
template <class Scalar>
Measured measure_row(methods::Method method, const ScalarType& scalar, const Prepared& p, double budget, bool quick) {
  Measured m;
  Row& row = m.row;
  row.method = std::string(methods::method_name(method));
  row.scalar = scalar;
  const auto start = Clock::now();
  measure_errors<Scalar>(row, scalar, p,
                         start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(budget / 2)),
                         [&](std::size_t i) { return evaluate<Scalar>(method, p.hinges[i].x); });
  const auto bits = scalar.mpfr_bits;
  m.timer = row_timer(
      row, p, budget / 2, quick, 3,
      [method](int g, const std::array<double, 12>& x, Slots& out, std::size_t i) {
        call_into<Scalar>(method, g, x, out, i);
      },
      [bits] {
        if constexpr (std::same_as<Scalar, mpfr>) set_mpfr_bits(bits);
        (void)bits;
      });
  row.seconds = seconds_since(start);
  return m;
}

#define HINGE_STUDY_ROW_EXTERN(S) \
  extern template Measured measure_row<S>(methods::Method, const ScalarType&, const Prepared&, double, bool);
HINGE_FOR_EACH_SCALAR(HINGE_STUDY_ROW_EXTERN)
#undef HINGE_STUDY_ROW_EXTERN

}  // namespace hinge::study::detail

// For the generated instantiation units (hinge_scalar_units in study/CMakeLists.txt), one per scalar family.
#define HINGE_STUDY_ROW_INSTANTIATE(S)                                          \
  template hinge::study::detail::Measured hinge::study::detail::measure_row<S>( \
      hinge::methods::Method, const hinge::ScalarType&, const hinge::study::detail::Prepared&, double, bool);
