// Exact geometric predicates on exact double inputs (hinge/core/predicates.hpp): a floating-point
// filter with a proved error bound decides the common case, exact rational arithmetic (GMP) the rest.
//
// Notation: u = 2^-53 (unit roundoff), fl(.) a rounded operation, gamma_k = k u / (1 - k u).
//
// Guard against underflow and overflow. Every filter below starts from differences d = fl(p - q) of
// input coordinates; it is used only when each difference is either exactly zero or has magnitude in
// [2^-L, 2^L] (L = 450 for the 2x2, L = 300 for the 3x3 determinant). A zero difference is exact (p = q)
// and makes every product it enters exactly zero. Otherwise every product of two differences lies in
// [2^-2L, 2^2L] and every product of three in [2^-3L, 2^3L] (for the 3x3 case see there), inside the
// normal range, and so is the error bound computed from them: each product has relative error <= u.
// Additions and subtractions never suffer from underflow (a subnormal sum is exact) and, with these
// magnitudes, cannot overflow. So the standard model fl(a op b) = (a op b)(1 + delta), |delta| <= u, holds
// for every operation, and the bounds below are rigorous. Inputs outside the guard (huge or tiny
// coordinates, subnormals, differences that overflow, NaN) go to the exact path; they are rare.
#include "hinge/core/predicates.hpp"

#include <boost/multiprecision/gmp.hpp>
#include <cmath>

#include "hinge/core/errors.hpp"

namespace hinge {
namespace {

using Rational = boost::multiprecision::mpq_rational;

constexpr double u = 0x1p-53;

// True when d is exactly zero or |d| is in [lo, hi]; false for NaN and infinities.
bool in_guard(double d, double lo, double hi) {
  const double a = std::fabs(d);
  return a == 0.0 || (a >= lo && a <= hi);
}

// 2x2 filter for D = a d - b c, a..d the exact differences, a' = fl(a) = a (1 + delta) etc. computed.
// Each computed product carries three roundings (two differences, the product), the subtraction one
// more, so with theta_k denoting factors |theta_k| <= gamma_k:
//   D' = fl(fl(a' d') - fl(b' c')) = a d (1 + theta_4) - b c (1 + theta_4'),  |D' - D| <= gamma_4 P,
// P = |a d| + |b c| (exact). The computed permanent P' = fl(|fl(a' d')| + |fl(b' c')|) >= (1 - gamma_4) P,
// so |D' - D| <= gamma_4 / (1 - gamma_4) P' < 4.001 u P' < 5 u (1 - u) P' <= fl(5 u P'). Hence
// |D'| > fl(5 u P') certifies D != 0 and sign D = sign D'. (Shewchuk's sharper (3 + 16 u) u uses that
// the last rounding cannot change a sign; 5 u is simpler to check and costs nothing here.)
// A computed product in the guard is zero only when a factor is an exactly zero difference, so P' == 0
// certifies D == 0 (the axis-aligned case, e.g. a planar mesh in z = 0).
// Returns the certified sign (-1, 0, +1), or kUnknown when the filter cannot decide.
constexpr int kUnknown = 2;

int orient2d_filter(double a, double b, double c, double d) {
  constexpr double lo = 0x1p-450, hi = 0x1p450;
  if (!(in_guard(a, lo, hi) && in_guard(b, lo, hi) && in_guard(c, lo, hi) && in_guard(d, lo, hi))) {
    return kUnknown;
  }
  const double ad = a * d, bc = b * c;
  const double det = ad - bc;
  const double perm = std::fabs(ad) + std::fabs(bc);
  const double bound = 5.0 * u * perm;
  if (perm == 0.0) return 0;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return kUnknown;
}

// Exact: every finite double is a dyadic rational. Non-finite values cannot be judged exactly.
Rational exact(double x) {
  if (!std::isfinite(x)) throw InputError("exact predicate: non-finite coordinate");
  return Rational(x);
}

}  // namespace

bool zero_area_exact(const Point& a, const Point& b, const Point& c) {
  // (b - a) x (c - a) has the three components det[[ub, vb], [uc, vc]] over the coordinate pairs (u, v) =
  // (y, z), (z, x), (x, y). The area is zero exactly when all three vanish; one certified nonzero
  // component decides "not zero".
  const double e[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double f[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  bool all_zero = true;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const int s = orient2d_filter(e[i], e[j], f[i], f[j]);
    if (s == 1 || s == -1) return false;
    all_zero = all_zero && s == 0;
  }
  if (all_zero) return true;
  // Exact path.
  Rational ex[3], fx[3];
  for (int k = 0; k < 3; ++k) {
    ex[k] = exact(b[k]) - exact(a[k]);
    fx[k] = exact(c[k]) - exact(a[k]);
  }
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    if (ex[i] * fx[j] != ex[j] * fx[i]) return false;
  }
  return true;
}

int hinge_orientation_exact(const Point& x0, const Point& x1, const Point& x2, const Point& x3) {
  // det[e0, x0 - x1, x1 - x3] = -det[p, q, r] with all columns taken from x1:
  //   p = x2 - x1, q = x0 - x1, r = x3 - x1.
  // det[p, q, r] = p_x (q_y r_z - q_z r_y) + p_y (q_z r_x - q_x r_z) + p_z (q_x r_y - q_y r_x).
  constexpr double lo = 0x1p-300, hi = 0x1p300;
  double p[3], q[3], r[3];
  bool guarded = true;
  for (int k = 0; k < 3; ++k) {
    p[k] = x2[k] - x1[k];
    q[k] = x0[k] - x1[k];
    r[k] = x3[k] - x1[k];
    guarded = guarded && in_guard(p[k], lo, hi) && in_guard(q[k], lo, hi) && in_guard(r[k], lo, hi);
  }
  if (guarded) {
    // 3x3 filter. Guard details: a pair product is 0 or in [2^-600, 2^600]; a nonzero minor fl(m1 - m2)
    // is a multiple of ulp(2^-600) = 2^-652 and at most 2^601, so a minor times a difference is 0 or in
    // [2^-952, 2^901], and the bound below is >= 2^-950: no underflow, no overflow.
    // Error, with p, q, r the exact differences and P = sum_k |p_k| (|m1_k| + |m2_k|) the exact permanent:
    // a computed pair product carries 3 roundings (two differences, the product), the minor 1, the term
    // p_k' * minor_k' 2 (p_k' itself and the product), and the sum of three terms (starting from an exact
    // 0 + T0) at most 2: |D' - D| <= gamma_8 P. The computed permanent has the same depth, P' >= (1 -
    // gamma_8) P, so |D' - D| <= gamma_8 / (1 - gamma_8) P' < 8.001 u P' < 9 u (1 - u) P' <= fl(9 u P').
    // Hence |D'| > fl(9 u P') certifies the sign. (Shewchuk's orient3d bound is (7 + 56 u) u with a
    // sharper count; 9 u is simpler to check and costs nothing in practice.)
    double det = 0.0, perm = 0.0;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double m1 = q[i] * r[j], m2 = q[j] * r[i];
      det += p[k] * (m1 - m2);
      perm += std::fabs(p[k]) * (std::fabs(m1) + std::fabs(m2));
    }
    const double bound = 9.0 * u * perm;
    // As in the 2x2 case, P' == 0 means every term has an exactly zero factor: D == 0.
    if (perm == 0.0) return 0;
    if (det > bound) return -1;  // the hinge determinant is -det[p, q, r]
    if (-det > bound) return 1;
  }
  // Exact path.
  Rational P[3], Q[3], R[3];
  for (int k = 0; k < 3; ++k) {
    const Rational base = exact(x1[k]);
    P[k] = exact(x2[k]) - base;
    Q[k] = exact(x0[k]) - base;
    R[k] = exact(x3[k]) - base;
  }
  Rational det = 0;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    det += P[k] * (Q[i] * R[j] - Q[j] * R[i]);
  }
  const int s = det.sign();
  return -s;
}

}  // namespace hinge
