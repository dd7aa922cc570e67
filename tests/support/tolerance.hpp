// tests/support/tolerance.hpp: the one tolerance rule of the test suite. Errors are measured in units
// of the unit roundoff u of the scalar type under test (u = 2^-53 for double), normwise:
//     error = ||computed - exact||_2 / ||exact||_2 / u,
// and every bound a test asserts is such a count of units, stated with its reason at the assertion.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

#include "hinge/core/scalar.hpp"

namespace hinge::test {

// Normwise relative error of `computed` against `exact` in units of `u`. Both are indexable with size().
// The difference is taken in the computed type (the exact value rounded to it first: at most half a
// unit), so that types wider than double are measured in their own units.
template <class A, class B>
double normwise_units(const A& computed, const B& exact, double u) {
  using Scalar = typename A::Scalar;
  long double difference = 0, norm = 0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(exact.size()); ++i) {
    const Scalar e = [&] {
      if constexpr (std::same_as<std::remove_cvref_t<decltype(exact.reshaped()[i])>, mpfr> && QdScalar<Scalar>)
        return from_mpfr<Scalar>(exact.reshaped()[i]);
      else return static_cast<Scalar>(exact.reshaped()[i]);
    }();
    const long double d = static_cast<long double>(to_double(Scalar(computed.reshaped()[i] - e)));
    const long double en = static_cast<long double>(to_double(e));
    difference += d * d;
    norm += en * en;
  }
  if (norm == 0) return difference == 0 ? 0 : INFINITY;
  return static_cast<double>(std::sqrt(difference / norm) / u);
}

// u of Scalar as a double (2^-24, 2^-53, 2^-64, 2^-113, or 2^-bits for mpfr).
template <class Scalar>
double unit_roundoff_double() {
  return to_double(unit_roundoff<Scalar>());
}

// The 12 coordinates in a failure message, each exactly.
inline std::string describe(const std::array<double, 12>& x) {
  std::ostringstream s;
  s.precision(17);
  s << "x = [";
  for (int i = 0; i < 12; ++i) s << (i ? ", " : "") << x[i];
  s << "]";
  return s.str();
}

// ---------------------------------------------------------------------------------------------------
// The rule, extended for the property suite (tests/properties, docs/testing.md).
//
// Every comparison is  error <= bound  with both sides in units of u of the scalar type under test:
//   error = ||a - b|| / max(||a||, ||b||, scale) / u        (normwise; scale 0 unless stated)
// and bound = c * kappa(x), c a constant per method and scalar type stated with its reason where it is
// declared (tests/properties/bounds.hpp), kappa the condition number of the hinge below. Two computed
// results of one exact quantity (an invariance) may differ by the sum of their bounds: 2 c kappa. A
// bound of 0 is a bit-exact claim.
// ---------------------------------------------------------------------------------------------------

// The condition number of a hinge (docs/testing.md, "Condition number"), computed from the exact input
// doubles in bin128 (113 bits; the value is needed to a few percent):
//
//   kappa_shape = max over the two triangles of  l_max / h_min = l_max^2 / (2A)        (h_i = 2A / l_i)
//   kappa_angle = min(kappa_shape, 1 / |sin theta|)
//   kappa       = kappa_shape * max(1, kappa_angle)
//
// kappa_shape is 2/sqrt(3) = 1.15 for an equilateral triangle, at most 1/0.15 = 6.7 on well-shaped hinges
// (docs/contract.md), and grows as 1/epsilon when an altitude (needle) or the hinge edge (then h1, h2 ~
// epsilon) collapses. It is the first-order condition of the problem: moving the vertices by delta l_max
// moves theta by ~kappa_shape delta, grad theta and Hess theta (~1/h, ~1/h^2) by ~kappa_shape delta
// relatively (measured: docs/testing.md).
// kappa_angle is the cancellation in eq. (6): N0 + N~0 (each of size 1/l0^2) cancels near flat and near
// folded hinges (|N0 + N~0| ~ |sin theta| / l0^2), while |Hess theta| can be as small as ~kappa_shape /
// l_max^2 (a short hinge edge), so errors of relative size e in the stencil's n, m0, l0 reach Hess theta
// amplified by ~min(kappa_shape, 1 / |sin theta|). Evaluations whose stencil carries errors e ~
// kappa_shape u (a cross product of a needle computed plainly: hinge::reference in long double, bin128)
// are then within c kappa u; with e ~ u (error-free cross products) within c kappa_shape u.
inline double shape_condition_number(const std::array<double, 12>& x);
inline double angle_condition_number(const std::array<double, 12>& x);

namespace detail {
struct HingeShape {
  double kappa_shape = 0;  // l_max^2 / (2A), the larger of the two triangles
  double sin_theta = 0;    // |n x n~|
};
inline HingeShape hinge_shape(const std::array<double, 12>& x) {
  using Q = bin128;
  using V = std::array<Q, 3>;
  auto edge = [&x](int a, int b) {
    return V{Q(x[3 * a]) - Q(x[3 * b]), Q(x[3 * a + 1]) - Q(x[3 * b + 1]), Q(x[3 * a + 2]) - Q(x[3 * b + 2])};
  };
  auto cross = [](const V& u, const V& v) {
    return V{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  };
  auto sq = [](const V& e) { return Q(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]); };
  HingeShape r;
  V normals[2];
  const int corners[2][3] = {{0, 1, 2}, {3, 2, 1}};  // T = (x0, x1, x2), T~ = (x3, x2, x1)
  for (int t = 0; t < 2; ++t) {
    const int a = corners[t][0], b = corners[t][1], c = corners[t][2];
    const V u = edge(b, a), v = edge(c, a), w = edge(c, b);
    normals[t] = cross(u, v);
    const Q double_area = sqrt(sq(normals[t]));
    if (double_area == 0) return {INFINITY, 0};
    r.kappa_shape = std::max(r.kappa_shape, to_double(Q(std::max({sq(u), sq(v), sq(w)}) / double_area)));
  }
  const V s = cross(normals[0], normals[1]);
  r.sin_theta = to_double(Q(sqrt(sq(s)) / sqrt(sq(normals[0]) * sq(normals[1]))));
  return r;
}
}  // namespace detail

inline double shape_condition_number(const std::array<double, 12>& x) { return detail::hinge_shape(x).kappa_shape; }

inline double angle_condition_number(const std::array<double, 12>& x) {
  const auto s = detail::hinge_shape(x);
  return std::min(s.kappa_shape, 1 / s.sin_theta);
}

inline double condition_number(const std::array<double, 12>& x) {
  const auto s = detail::hinge_shape(x);
  return s.kappa_shape * std::max(1.0, std::min(s.kappa_shape, 1 / s.sin_theta));
}

// Normwise distance of two results of one type (both computed), in units of u:
// ||a - b|| / max(||a||, ||b||, scale) / u. Accumulated in the type itself (no overflow to double).
template <class A, class B>
double normwise_units_between(const A& a, const B& b, double u, double scale = 0) {
  using Scalar = typename A::Scalar;
  Scalar difference = 0, na = 0, nb = 0;
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(a.size()); ++i) {
    const Scalar d = a.reshaped()[i] - b.reshaped()[i];
    difference += d * d;
    na += a.reshaped()[i] * a.reshaped()[i];
    nb += b.reshaped()[i] * b.reshaped()[i];
  }
  const double denominator = std::max({to_double(Scalar(sqrt(na))), to_double(Scalar(sqrt(nb))), scale});
  if (denominator == 0) return difference == 0 ? 0 : INFINITY;
  return to_double(Scalar(sqrt(difference))) / denominator / u;
}

// |a - b| / max(|a|, |b|, scale) / u for two scalars of one type.
template <class Scalar>
double scalar_units(const Scalar& a, const Scalar& b, double u, double scale = 0) {
  const double denominator = std::max({std::abs(to_double(a)), std::abs(to_double(b)), scale});
  const double difference = std::abs(to_double(Scalar(a - b)));
  if (denominator == 0) return difference == 0 ? 0 : INFINITY;
  return difference / denominator / u;
}

// The number of doubles strictly between a and b, plus one (0 when equal; for failure messages).
inline double ulps_apart(double a, double b) {
  if (a == b) return 0;
  if (!std::isfinite(a) || !std::isfinite(b)) return INFINITY;
  auto ordered = [](double v) {  // the doubles in order as integers
    std::int64_t i;
    std::memcpy(&i, &v, sizeof i);
    return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;
  };
  return std::abs(static_cast<double>(ordered(a)) - static_cast<double>(ordered(b)));
}

// A value at full precision (max_digits10 significant digits: it reads back exactly); an mpfr value (whose
// precision is chosen at run time) to 40 significant digits, beyond any type it is compared with.
template <class Scalar>
std::string show_exactly(const Scalar& v) {
  std::ostringstream s;
  if constexpr (std::same_as<Scalar, mpfr>) s.precision(40);
  else s.precision(std::numeric_limits<Scalar>::max_digits10);
  s << v;
  return s.str();
}

// Every entry of a vector or matrix at full precision, row-major.
template <class M>
std::string show_exactly_all(const M& m) {
  std::ostringstream s;
  s << "[";
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Eigen::Index c = 0; c < m.cols(); ++c) s << (r || c ? ", " : "") << show_exactly(m(r, c));
  s << "]";
  return s.str();
}

// ---------------------------------------------------------------------------------------------------
// The constants c of bound = c kappa (units of u of the type), one per method and scalar type. Each is
// the worst units / kappa measured on 3000 random hinges per family (well-shaped and the hard families,
// against MPFR at 256 bits and against finite differences of an independent theta; docs/testing.md),
// times a margin of about 3 so that a deep run (10000 cases) does not trip over a rarer worst case.
// ---------------------------------------------------------------------------------------------------
template <class Scalar>
double reference_units_per_kappa() {
  if constexpr (std::same_as<Scalar, double>) return 4;  // measured worst 1.4 (double: stencil in long double)
  else return 8;                                         // bin128 (stencil in its own format): measured worst 3.0
}
template <class Scalar>
double reference_units(double kappa) {
  return reference_units_per_kappa<Scalar>() * kappa;
}
template <class Scalar>
std::string reference_reason() {
  std::ostringstream s;
  s << "reference accuracy c kappa, c = " << reference_units_per_kappa<Scalar>() << " (about 3 x the measured worst)";
  return s.str();
}

// Energy derivatives of one hinge (reference::assemble on two faces) against finite differences of an
// independent energy, on the scale of mesh_support.hpp: the theta derivatives' errors carried through
// psi', psi'' and the chain rule (eqs. (2)-(3)). Measured worst units / kappa on 2000 hinges per type: 1.7
// (double), 2.6 (bin128).
template <class Scalar>
double energy_units_per_kappa() {
  return std::same_as<Scalar, double> ? 6 : 8;
}
template <class Scalar>
double energy_units(double kappa) {
  return energy_units_per_kappa<Scalar>() * kappa;
}
template <class Scalar>
std::string energy_reason() {
  std::ostringstream s;
  s << "energy derivatives c kappa, c = " << energy_units_per_kappa<Scalar>() << " (about 3 x the measured worst)";
  return s.str();
}

// A mesh's E, grad E, Hess E from hinge::reference::assemble (sums of hinge terms), on the scales of
// mesh_support.hpp, kappa the largest hinge condition number. Two evaluations (relabelled, reversed)
// differ by at most 2 c kappa: measured worst 2.05 kappa on 2000 meshes, so c = 4 (margin 4 on 2 c).
template <class Scalar>
double mesh_units(double kappa) {
  return 4 * kappa;
}
template <class Scalar>
std::string mesh_reason() {
  return "reference mesh c kappa, c = 4";
}

// hinge::fast's per-hinge kernel against MPFR at 256 bits: measured worst units / kappa on 2000 hinges
// per family 1.23 (double) and 3.7 (bin128, well-shaped). For double the kernel's stencil is computed in
// double-double and rounded once, and the error is also within c kappa_shape (measured 1.32): the
// property FastDouble.NearDegenerateWithinShapeCondition asserts that stronger claim.
template <class Scalar>
double fast_units_per_kappa() {
  return std::same_as<Scalar, double> ? 4 : 12;
}
template <class Scalar>
double fast_units(double kappa) {
  return fast_units_per_kappa<Scalar>() * kappa;
}
template <class Scalar>
std::string fast_reason() {
  std::ostringstream s;
  s << "fast kernel c kappa, c = " << fast_units_per_kappa<Scalar>() << " (about 3 x the measured worst)";
  return s.str();
}
// hinge::fast's mesh assembly (Algorithm 2) on the scales of mesh_support.hpp: fast against the reference
// measured worst 2.6 kappa (double), 2.4 kappa (bin128) on 2000 meshes, against a bound of (4 + 4) kappa.
template <class Scalar>
double fast_mesh_units(double kappa) {
  return 4 * kappa;
}
template <class Scalar>
std::string fast_mesh_reason() {
  return "fast mesh c kappa, c = 4";
}

}  // namespace hinge::test
