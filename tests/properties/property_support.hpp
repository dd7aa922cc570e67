// tests/properties/property_support.hpp: what the property files share: evaluation in the scalar types
// under test and in MPFR, an independent theta (written here from docs/contract.md, no library code) and
// its finite differences, the failure report, and the measured worst error of each property (printed at
// exit with HINGE_TEST_MEASURE=1; docs/testing.md quotes them).
#pragma once

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cstdio>
#include <map>
#include <mutex>
#include <sstream>
#include <string>

#include "hinge/core/errors.hpp"
#include "hinge/reference/evaluate.hpp"
#include "support/generators.hpp"
#include "support/tolerance.hpp"

namespace hinge::test {

// The precision of the higher-precision evaluations: MPFR at 256 bits, 143 bits beyond bin128's 113.
inline constexpr unsigned exact_bits = 256;

template <class Scalar>
double u_of() {
  return unit_roundoff_double<Scalar>();
}

template <class Scalar>
std::string type_name() {
  return scalar_name<Scalar>();
}

// The worst error / bound ratio and error seen per property, printed at exit when HINGE_TEST_MEASURE=1.
class Measurements {
 public:
  static Measurements& get() {
    static Measurements m;
    return m;
  }
  void record(const std::string& what, double units, double kappa) {
    std::lock_guard<std::mutex> lock(mutex_);
    Entry& e = entries_[what];
    e.worst_units = std::max(e.worst_units, units);
    if (kappa > 0) e.worst_per_kappa = std::max(e.worst_per_kappa, units / kappa);
    e.worst_kappa = std::max(e.worst_kappa, kappa);
    ++e.count;
  }
  ~Measurements() {
    const char* flag = std::getenv("HINGE_TEST_MEASURE");
    if (!flag || std::string(flag) != "1") return;
    for (const auto& [what, e] : entries_)
      std::printf("[ measured ] %-70s n=%-6ld worst %10.3g units, worst units/kappa %8.3g, largest kappa %8.3g\n",
                  what.c_str(), e.count, e.worst_units, e.worst_per_kappa, e.worst_kappa);
  }

 private:
  struct Entry {
    double worst_units = 0, worst_per_kappa = 0, worst_kappa = 0;
    long count = 0;
  };
  std::map<std::string, Entry> entries_;
  std::mutex mutex_;
};

// The seed RapidCheck runs with (printed at start as "Using configuration: seed=..."); a failure also
// prints a `reproduce=` string: RC_PARAMS="reproduce=..." replays exactly the shrunk counterexample.
inline std::string replay_hint() {
  std::ostringstream s;
  s << "replay: RapidCheck seed " << rc::detail::configuration().testParams.seed
    << " (RC_PARAMS=\"seed=" << rc::detail::configuration().testParams.seed
    << "\" with --gtest_filter=<this test>, or the reproduce= string RapidCheck prints at exit)";
  return s.str();
}

// A failed comparison: everything needed to see why, and to replay it. Each result is printed in full
// at the precision of its type (max_digits10: reads back exactly).
struct Report {
  std::ostringstream text;
  explicit Report(const std::string& property) { text << property << " failed\n"; }
  Report(const std::string& property, const Coordinates& x) {
    text << property << " failed\n  input " << describe(x) << "\n  kappa = " << condition_number(x) << " (kappa_shape "
         << shape_condition_number(x) << ", kappa_angle " << angle_condition_number(x) << ")\n";
  }
  template <class T>
  Report& value(const std::string& name, const T& v) {
    text << "  " << name << " = " << show_exactly(v) << "\n";
    return *this;
  }
  template <class M>
  Report& values(const std::string& name, const M& m) {
    text << "  " << name << " = " << show_exactly_all(m) << "\n";
    return *this;
  }
  Report& line(const std::string& s) {
    text << "  " << s << "\n";
    return *this;
  }
  // The error in units of u against its bound, the worst entry in ulps of double, and the replay hint.
  template <class A, class B>
  std::string finish(double units, double bound, const std::string& reason, const A& a, const B& b) {
    double worst_ulps = 0;
    Eigen::Index worst = 0;
    for (Eigen::Index i = 0; i < a.size(); ++i) {
      const double d = ulps_apart(to_double(a.reshaped()[i]), to_double(b.reshaped()[i]));
      if (d > worst_ulps) worst_ulps = d, worst = i;
    }
    text << "  error " << units << " units of u > bound " << bound << " (" << reason << ")\n  worst entry " << worst
         << " (row-major " << worst / std::max<Eigen::Index>(a.cols(), 1) << ", "
         << worst % std::max<Eigen::Index>(a.cols(), 1) << "): " << show_exactly(a.reshaped()[worst]) << " vs "
         << show_exactly(b.reshaped()[worst]) << ", " << worst_ulps << " ulps of double apart\n  " << replay_hint();
    return text.str();
  }
  std::string finish(double units, double bound, const std::string& reason) {
    text << "  error " << units << " units of u > bound " << bound << " (" << reason << ")\n  " << replay_hint();
    return text.str();
  }
};

// Fails the property (with the report built by `make_report`) unless units <= bound; records the measure.
template <class MakeReport>
void check_units(const std::string& measure, double units, double bound, double kappa, MakeReport&& make_report) {
  Measurements::get().record(measure, units, kappa);
  if (!(units <= bound)) RC_FAIL(make_report());
}

// The higher-precision evaluation of the reference formulas.
inline reference::ThetaDerivatives<mpfr> exact_derivatives(const Coordinates& x) {
  set_mpfr_bits(exact_bits);
  return reference::theta_derivatives<mpfr>(x);
}

// ---------------------------------------------------------------------------------------------------
// An independent theta, straight from docs/contract.md (no code of the library):
//   N = (x1 - x0) x (x2 - x0),  Nt = (x2 - x3) x (x1 - x3),  e0 = x2 - x1,
//   theta = atan2(((N x Nt) . e0) / |e0|, N . Nt)
// and its central finite differences in MPFR (fd_bits), with steps h = 2^-120 l (l the largest coordinate
// difference). Truncation error ~ (h kappa / l)^2 <= 2^-154 for kappa <= 2^43; rounding error of the
// differences ~ kappa 2^-fd_bits / h^2 relative to |Hess| ~ kappa^2 / l^2: 2^(240 - fd_bits) = 2^-160. Both
// far below bin128's u = 2^-113: the differences are an exact evaluation for these tests.
// ---------------------------------------------------------------------------------------------------
inline constexpr unsigned fd_bits = 400;

struct Independent {
  mpfr theta;
  Eigen::Matrix<mpfr, 12, 1> grad;
  Eigen::Matrix<mpfr, 12, 12> hess;
};

inline mpfr independent_theta(const std::array<mpfr, 12>& x) {
  auto sub = [&x](int a, int b) {
    return std::array<mpfr, 3>{x[3 * a] - x[3 * b], x[3 * a + 1] - x[3 * b + 1], x[3 * a + 2] - x[3 * b + 2]};
  };
  auto cross = [](const std::array<mpfr, 3>& p, const std::array<mpfr, 3>& q) {
    return std::array<mpfr, 3>{p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
  };
  auto dot = [](const std::array<mpfr, 3>& p, const std::array<mpfr, 3>& q) {
    return mpfr(p[0] * q[0] + p[1] * q[1] + p[2] * q[2]);
  };
  const auto N = cross(sub(1, 0), sub(2, 0)), Nt = cross(sub(2, 3), sub(1, 3)), e0 = sub(2, 1);
  return atan2(dot(cross(N, Nt), e0) / sqrt(dot(e0, e0)), dot(N, Nt));
}

inline double largest_difference(const Coordinates& x) {
  double s = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < a; ++b)
      for (int c = 0; c < 3; ++c) s = std::max(s, std::abs(x[3 * a + c] - x[3 * b + c]));
  return s;
}

// theta, and grad and Hess by central differences, of any function f of the 12 coordinates (in MPFR).
template <class F>
Independent finite_differences(const Coordinates& x, F&& f) {
  set_mpfr_bits(fd_bits);
  std::array<mpfr, 12> p;
  for (int i = 0; i < 12; ++i) p[i] = x[i];
  const mpfr h = ldexp(mpfr(largest_difference(x)), -120);
  Independent r;
  r.theta = f(p);
  for (int i = 0; i < 12; ++i) {
    auto plus = p, minus = p;
    plus[i] += h;
    minus[i] -= h;
    r.grad[i] = (f(plus) - f(minus)) / (2 * h);
  }
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j <= i; ++j) {
      auto at = [&](int si, int sj) {
        auto y = p;
        y[i] += si * h;
        y[j] += sj * h;
        return f(y);
      };
      r.hess(i, j) = r.hess(j, i) = (at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4 * h * h);
    }
  return r;
}

}  // namespace hinge::test
