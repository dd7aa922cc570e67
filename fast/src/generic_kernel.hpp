// fast/src/generic_kernel.hpp: the per-hinge kernel of hinge/fast/hinge_kernel.hpp for every scalar type
// (double has its own, in eight lanes: hinge_kernel_lanes.hpp; its wide-range fallback is this one in long
// double), and the fallback for hinges outside the double kernel's range.
//
// Each triangle is summarised by (proofs/hessian.md for the identities):
//   n        unit normal (n~ for the lower triangle)
//   q_j      m_j / h_j = (e_j x C) / |C|^2, C = e1 x e2 (q_0 + q_1 + q_2 = 0; -q_j is the gradient of the
//            barycentric coordinate of vertex j)
//   a_0      1 / h_0 = l_0 / (2A)
//   a_1      cos(alpha_2) / h_1 = -(e_0 . e_1) / (l_0 2A)     (a_1 + a_2 = a_0)
//   a_2      cos(alpha_1) / h_2 = -(e_2 . e_0) / (l_0 2A)
//   r_0      m_0 / l_0^2, so that eq. (5)'s N_0 = n r_0^T
// and eqs. (4)-(6) read, with the errata applied (P_1j carries cos(alpha_2), Q~_j takes omega~_0j):
//   grad_x0 = -a_0 n,  grad_x1 = a_1 n + a~_1 n~,  grad_x2 = a_2 n + a~_2 n~,  grad_x3 = -a~_0 n~    eq. (4)
//   Q_j = omega_0j M_j = a_0 n q_j^T,  P_ij = omega_ij cos(alpha_{3-i}) M_j^T = a_i q_j n^T          eq. (5)
//   H00 = -S(Q_0),  H10 = P_10 - Q_1,  H20 = P_20 - Q_2,  H11 = S(P_11) + S(P~_11) - (N_0 + N~_0),
//   H22 = S(P_22) + S(P~_22) - (N_0 + N~_0),  H12 = P_12 + P_21^T + P~_12 + P~_21^T + N_0 + N~_0,
//   H03 = 0, the tilde blocks alike, and H_ji = H_ij^T                                               eq. (6)
//
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "columns.hpp"
#include "exact.hpp"
#include "faithful_theta.hpp"
#include "hinge/core/hinge_checks.hpp"
#include "hinge/core/predicates.hpp"
#include "hinge/fast/hinge_kernel.hpp"

namespace hinge::fast {

// The per-triangle summary of the header comment, in Scalar.
template <class Scalar>
struct HingeTriangle {
  std::array<Scalar, 3> n;                 // unit normal (n, or n~ for the lower triangle)
  std::array<std::array<Scalar, 3>, 3> q;  // q_j = m_j / h_j
  std::array<Scalar, 3> a;                 // a_0 = 1/h_0, a_1 = cos(alpha_2)/h_1, a_2 = cos(alpha_1)/h_2
  std::array<Scalar, 3> r0;                // m_0 / l_0^2
};

namespace detail {

// The type the per-triangle quantities are computed in before they are rounded to Scalar once, two
// triangles at a time (lane 0 the upper, lane 1 the lower): two doubles for float; two double-doubles
// for long double (DD2: the double kernel's arithmetic, exact differences and error-free products, about
// 106 bits against long double's 64, so that long double beats the conditioning of needles and short
// hinge edges as double does: docs/numerics.md); a pair of Scalar otherwise (float128, bin128, mpfr,
// dd, qd: the differences of the input doubles are exact in them within an exponent gap of p - 53 bits).
// (double has its own kernel in lanes, src/hinge_kernel_lanes.hpp.)
template <class W>
struct Pair {
  W v[2];
  HINGE_FAST_INLINE W& operator[](int i) { return v[i]; }
  HINGE_FAST_INLINE const W& operator[](int i) const { return v[i]; }
  friend HINGE_FAST_INLINE Pair operator+(const Pair& a, const Pair& b) { return {{a[0] + b[0], a[1] + b[1]}}; }
  friend HINGE_FAST_INLINE Pair operator-(const Pair& a, const Pair& b) { return {{a[0] - b[0], a[1] - b[1]}}; }
  friend HINGE_FAST_INLINE Pair operator*(const Pair& a, const Pair& b) { return {{a[0] * b[0], a[1] * b[1]}}; }
  friend HINGE_FAST_INLINE Pair operator-(const Pair& a) { return {{-a[0], -a[1]}}; }
};
using DD2 = DoubleDoubleOf<Lanes2>;
template <class Scalar>
struct WideOf {
  using type = Pair<Scalar>;
};
template <>
struct WideOf<float> {
  using type = Lanes2;
};
template <>
struct WideOf<long double> {
  using type = DD2;
};
template <class Scalar>
using Wide = typename WideOf<Scalar>::type;
// Whether W's range is double's (float's and long double's kernels): the kernel then checks in_range()
// and falls back to wide_range_kernel outside it.
template <class W>
inline constexpr bool kDoubleRange = std::is_same_v<W, Lanes2> || std::is_same_v<W, DD2>;

template <class W>
using Vec = std::array<W, 3>;

// --- arithmetic in the wide type ------------------------------------------------------------------

template <class W>
HINGE_FAST_INLINE W dot(const Vec<W>& a, const Vec<W>& b) {
  if constexpr (kDoubleDoubleOfDoubles<W>) {
    // Exact products of the high parts and their exact sum (two_prod, two_sum); their errors and the
    // first-order terms of the low parts (each formed apart: a short chain of dependent operations)
    // gathered in one double.
    const auto p0 = two_prod(a[0].hi, b[0].hi), p1 = two_prod(a[1].hi, b[1].hi), p2 = two_prod(a[2].hi, b[2].hi);
    const auto s1 = two_sum(p0.hi, p1.hi), s2 = two_sum(s1.hi, p2.hi);
    const auto t0 = fused(a[0].hi, b[0].lo, a[0].lo * b[0].hi), t1 = fused(a[1].hi, b[1].lo, a[1].lo * b[1].hi),
               t2 = fused(a[2].hi, b[2].lo, a[2].lo * b[2].hi);
    return fast_two_sum(s2.hi, (((p0.lo + p1.lo) + (p2.lo + s1.lo)) + s2.lo) + ((t0 + t1) + t2));
  } else {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }
}

// a b - c d
template <class W>
HINGE_FAST_INLINE W difference_of_products(const W& a, const W& b, const W& c, const W& d) {
  if constexpr (kDoubleDoubleOfDoubles<W>) {
    const auto p = two_prod(a.hi, b.hi), r = two_prod(c.hi, d.hi);
    const auto s = two_diff(p.hi, r.hi);
    const auto t = fused(a.hi, b.lo, a.lo * b.hi) - fused(c.hi, d.lo, c.lo * d.hi);
    return fast_two_sum(s.hi, ((p.lo - r.lo) + s.lo) + t);
  } else if constexpr (std::is_same_v<W, Lanes2>) {
    const Lanes2 cd = c * d;  // Kahan: error <= 2 units (float's quantities are computed in double)
    return fused(a, b, -cd) + fused(-c, d, cd);
  } else {
    return a * b - c * d;
  }
}

template <class W>
HINGE_FAST_INLINE Vec<W> cross(const Vec<W>& a, const Vec<W>& b) {
  return {difference_of_products(a[1], b[2], a[2], b[1]), difference_of_products(a[2], b[0], a[0], b[2]),
          difference_of_products(a[0], b[1], a[1], b[0])};
}

template <class W>
HINGE_FAST_INLINE W inverse_sqrt(const W& a) {
  if constexpr (std::is_same_v<W, Lanes2>) return splat<Lanes2>(1) / root(a);
  else if constexpr (std::is_same_v<W, DD2>) {
    // y = 1 / sqrt(a.hi) to a few units of 2^-53, then Newton's step as a factor (rsqrt_correction): y (1 +
    // h), relative error ~2^-100.
    const Lanes2 y = splat<Lanes2>(1) / root(a.hi);
    return fast_two_sum(y, y * rsqrt_correction(a, y));
  } else {
    using std::sqrt;
    using E = std::remove_cvref_t<decltype(a[0])>;
    return W{{E(1) / sqrt(a[0]), E(1) / sqrt(a[1])}};
  }
}

// a b rounded to Scalar once, lane by lane (DD2: the double-double product, relative error ~2^-104,
// then hi + lo rounded to long double).
template <class Scalar, class W>
HINGE_FAST_INLINE std::array<Scalar, 2> product_rounded(const W& a, const W& b) {
  if constexpr (std::is_same_v<W, DD2>) {
    const DD2 r = a * b;
    return {static_cast<Scalar>(static_cast<Scalar>(r.hi[0]) + static_cast<Scalar>(r.lo[0])),
            static_cast<Scalar>(static_cast<Scalar>(r.hi[1]) + static_cast<Scalar>(r.lo[1]))};
  } else if constexpr (std::is_same_v<W, Lanes2>) {
    const Lanes2 r = a * b;
    return {static_cast<Scalar>(r[0]), static_cast<Scalar>(r[1])};
  } else {
    return {static_cast<Scalar>(a[0] * b[0]), static_cast<Scalar>(a[1] * b[1])};
  }
}

// x_a - x_b (lane 0) and x_c - x_d (lane 1) of the input doubles, in W.
template <class W>
HINGE_FAST_INLINE W difference(double xa, double xb, double xc, double xd) {
  if constexpr (std::is_same_v<W, DD2>) {
    return two_diff(Lanes2{xa, xc}, Lanes2{xb, xd});  // exact
  } else if constexpr (std::is_same_v<W, Lanes2>) {
    return Lanes2{xa, xc} - Lanes2{xb, xd};
  } else {
    using E = std::remove_cvref_t<decltype(std::declval<W>()[0])>;
    return W{{from_double<E>(xa) - from_double<E>(xb), from_double<E>(xc) - from_double<E>(xd)}};
  }
}

// Lane i of a wide value, as a double (its high part) for the filters.
template <class W>
HINGE_FAST_INLINE double high_part(const W& a, int i) {
  if constexpr (std::is_same_v<W, DD2>) return a.hi[i];
  else if constexpr (std::is_same_v<W, Lanes2>) return a[i];
  else return to_double(a[i]);
}

// --- two triangles at once ------------------------------------------------------------------------

// The summaries of the upper (lane 0) and lower (lane 1) triangles, with edges f0, f1, f2 (f0 + f1 + f2
// = 0) whose labels run counter-clockwise about C = f1 x f2 = f2 x f0 (given: C = 2A n, the cross product
// with the hinge edge, so that it stays accurate when f0 is short), L0 = l_0^2 and S = (2A)^2: for the
// upper triangle C = N, for the lower (clockwise labels) C = -Nt, and the caller negates the lower
// normal. Also returns the unit normal C / |C| in W (for theta).
//
// Range (double-double, and float's double lanes): the caller checks in_range() below, where P2 is
// 2^-2m, with 2^m <= M < 2^(m+1), M in [2^-200, 2^201) the largest component of the edges (so that the
// check is exactly invariant under power-of-two scaling); when it fails, some intermediate here could
// leave the normal range, and the caller discards the results for wide_range_kernel's.
// The check: s = (2A)^2 / M^4 >= 2^-144 and lambda = l_0^2 / M^2 >= 2^-502 in both lanes (tested as
// S P2^2 >= 2^-140 and L0 P2 >= 2^-500, P2 M^2 in [1, 4)). Then, with l <= sqrt(3) M for every edge and
// 2A <= l_i l_j for any two of a triangle's edges (so l_1, l_2 >= 2A / (sqrt(3) M)), every intermediate
// stays in [2^-944, 2^944] (magnitudes of vectors), and double-double values in [2^-969, 2^1023] keep
// their low parts normal (relative error ~2^-104):
//   L0 = l_0^2                in [2^-902, 2^404]
//   D1, D2 = e_i . e_0         |.| <= 3 M^2 (may cancel to 0: absolute error ~2^-104 l_i l_0, and a product
//                              below 2^-969 that loses its error term adds at most 2^-1074)
//   S = (2A)^2                 in [2^-944, 2^808];      |C| = 2A in [2^-472, 2^404]
//   X1, X2 = (2A)^2 q_j        |X_j| = l_j 2A in [s M^3 / sqrt(3), 3 sqrt(3) M^3] within [2^-745, 2^606]
//   X0 = e_0 x C               |X0| = l_0 2A = sqrt(lambda s) M^3 in [2^-923, 2^606]
//   rA = 1/2A, invS = 1/(2A)^2 in [2^-404, 2^472], [2^-808, 2^944]
//   rl0 = 1/l_0, RL = 1/l_0^2   in [2^-203, 2^451], [2^-404, 2^902]
//   K = 1/(l_0 2A) = 1/|X0|    in [2^-606, 2^923];   X0 K = m_0, a unit vector
//   products of components (in the cross and dot products) may underflow: at most 2^-1074 each, against
//   results above 2^-923
// and the results: n unit, |q_j|, |a_j| <= 1/h_min <= sqrt(3) / (sqrt(s) M) < 2^274, |r_0| = 1/l_0^2 <=
// 2^902; eq. (6) (in double) then forms a_i q_j and r_0 (entries below 2^902). Hinges outside the check
// have kappa_shape above ~2^70 or a hinge edge below 2^-251 M: results there carry no guaranteed digit.
// After rescaling (M in [1, 2)) the same bounds hold a fortiori.
template <class W>
HINGE_FAST_INLINE bool in_range(const W& L0, const W& S, double P2) {
  if constexpr (std::is_same_v<W, DD2>) {
    return in_range(L0.hi, S.hi, P2);
  } else if constexpr (std::is_same_v<W, Lanes2>) {
    const Lanes2 s = (S * P2) * P2, lambda = L0 * P2;
    return s[0] >= 0x1p-140 && s[1] >= 0x1p-140 && lambda[0] >= 0x1p-500;
  } else {
    (void)L0, (void)S, (void)P2;
    return true;
  }
}

template <class Scalar, class W>
HINGE_FAST_INLINE void triangles(const Vec<W>& f0, const Vec<W>& f1, const Vec<W>& f2, const Vec<W>& C, const W& L0,
                                 const W& S, HingeTriangle<Scalar>& T, HingeTriangle<Scalar>& U, Vec<W>& unit_normal) {
  const W D1 = dot(f2, f0);                                              // e_2 . e_0
  const W D2 = dot(f0, f1);                                              // e_0 . e_1
  const Vec<W> X0 = cross(f0, C), X1 = cross(f1, C), X2 = cross(f2, C);  // (2A)^2 q_j
  const W rA = inverse_sqrt(S);                                          // 1 / (2A)
  const W invS = rA * rA;
  const W rl0 = inverse_sqrt(L0);  // 1 / l_0
  const W K = rA * rl0;            // 1 / (l_0 2A)
  const W RL = rl0 * rl0;          // 1 / l_0^2
  HINGE_FAST_UNROLL
  for (int k = 0; k < 3; ++k) {
    unit_normal[k] = C[k] * rA;
    auto set = [k, &T, &U](auto member, const std::array<Scalar, 2>& v) {
      member(T)[k] = v[0];
      member(U)[k] = v[1];
    };
    set(
        [](auto& t) -> auto& { return t.n; }, product_rounded<Scalar>(C[k], rA));
    set(
        [](auto& t) -> auto& { return t.q[0]; }, product_rounded<Scalar>(X0[k], invS));
    set(
        [](auto& t) -> auto& { return t.q[1]; }, product_rounded<Scalar>(X1[k], invS));
    set(
        [](auto& t) -> auto& { return t.q[2]; }, product_rounded<Scalar>(X2[k], invS));
    // r_0 = m_0 / l_0^2 with m_0 = X0 K: never 1 / (l_0^3 2A), which can overflow when r_0 does not
    set(
        [](auto& t) -> auto& { return t.r0; }, product_rounded<Scalar>(X0[k] * K, RL));
  }
  const std::array<Scalar, 2> a0 = product_rounded<Scalar>(L0, K);  // 1/h_0 = l_0 / (2A)
  const std::array<Scalar, 2> a1 = product_rounded<Scalar>(D2, K);  // cos(alpha_2)/h_1 = -(e_0 . e_1) / (l_0 2A)
  const std::array<Scalar, 2> a2 = product_rounded<Scalar>(D1, K);  // cos(alpha_1)/h_2 = -(e_2 . e_0) / (l_0 2A)
  T.a = {a0[0], Scalar(-a1[0]), Scalar(-a2[0])};
  U.a = {a0[1], Scalar(-a1[1]), Scalar(-a2[1])};
}

// The exact sign of theta: the filter of exact.hpp, else hinge_orientation_exact.
inline int orientation(const std::array<double, 12>& x, const double p[3], const double q[3], const double r[3]) {
  double computed;
  const int s = orientation_filter(p, q, r, computed);
  if (s != kUndecided) return s;
  return hinge_orientation_exact({x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}, {x[9], x[10], x[11]});
}

// --- eqs. (4)-(6) from the two summaries -----------------------------------------------------------

// Writes the Hessian of theta (12 x 12, column-major: `hess` points to its 144 entries) from the upper
// and lower summaries, column by column of each 3 x 3 block (columns.hpp). With M_j = n q_j^T (eq. (5)'s
// omega_0j M_j = a_0 M_j), the blocks of one half-hinge are
//   -S(Q_0) = -a_0 (M_0 + M_0^T),  P_10 - Q_1 = a_1 M_0^T - a_0 M_1,  P_20 - Q_2 = a_2 M_0^T - a_0 M_2,
//   S(P_11) = a_1 (M_1 + M_1^T),  S(P_22) = a_2 (M_2 + M_2^T),  P_12 + P_21^T = a_1 M_2^T + a_2 M_1,
// and N_0 = n r_0^T. Column c of M_j is n q_j[c], of M_j^T it is q_j n[c]. Each block below the diagonal
// is formed from the same products as its mirror, in the same order: the Hessian is exactly symmetric.
template <class Scalar>
HINGE_FAST_INLINE void hessian(const HingeTriangle<Scalar>& T, const HingeTriangle<Scalar>& U, Scalar* hess) {
  using C = Column<Scalar>;
  struct Half {
    C n, q0, q1, q2, r0;
    Scalar a0, a1, a2;
  };
  auto half = [](const HingeTriangle<Scalar>& t) {
    return Half{column(t.n), column(t.q[0]), column(t.q[1]), column(t.q[2]), column(t.r0), t.a[0], t.a[1], t.a[2]};
  };
  const Half A = half(T), B = half(U);  // eq. (6), left column and right column (tilde quantities)
  auto at = [hess](int I, int J, int c) { return hess + 12 * (3 * J + c) + 3 * I; };  // block (I, J), column c
  const C zero = column<Scalar>(Scalar(0), Scalar(0), Scalar(0));
  HINGE_FAST_UNROLL
  for (int c = 0; c < 3; ++c) {
    // N_0 + N~_0 is symmetric (proofs/half-hinge.md); its symmetric part, formed symmetrically, keeps the
    // diagonal blocks exactly symmetric.
    const C sym = ((A.n * A.r0[c] + B.n * B.r0[c]) + (A.r0 * A.n[c] + B.r0 * B.n[c])) / Scalar(2);
    store<Scalar>(at(0, 0, c), -(A.a0 * (A.n * A.q0[c] + A.q0 * A.n[c])));  // H00 = -S(Q_0)
    store<Scalar>(at(3, 3, c), -(B.a0 * (B.n * B.q0[c] + B.q0 * B.n[c])));  // H33
    store<Scalar>(at(1, 1, c), (A.a1 * (A.n * A.q1[c] + A.q1 * A.n[c]) + B.a1 * (B.n * B.q1[c] + B.q1 * B.n[c])) - sym);
    store<Scalar>(at(2, 2, c), (A.a2 * (A.n * A.q2[c] + A.q2 * A.n[c]) + B.a2 * (B.n * B.q2[c] + B.q2 * B.n[c])) - sym);
    // H12 = P_12 + P_21^T + P~_12 + P~_21^T + N_0 + N~_0, and H21 = H12^T
    store<Scalar>(
        at(1, 2, c),
        ((A.a1 * (A.q2 * A.n[c]) + A.a2 * (A.n * A.q1[c])) + (B.a1 * (B.q2 * B.n[c]) + B.a2 * (B.n * B.q1[c]))) + sym);
    store<Scalar>(
        at(2, 1, c),
        ((A.a1 * (A.n * A.q2[c]) + A.a2 * (A.q1 * A.n[c])) + (B.a1 * (B.n * B.q2[c]) + B.a2 * (B.q1 * B.n[c]))) + sym);
    // H10 = P_10 - Q_1 (erratum 1: cos(alpha_2) with vertex 1), H20 = P_20 - Q_2, and their mirrors
    store<Scalar>(at(1, 0, c), A.a1 * (A.q0 * A.n[c]) - A.a0 * (A.n * A.q1[c]));
    store<Scalar>(at(0, 1, c), A.a1 * (A.n * A.q0[c]) - A.a0 * (A.q1 * A.n[c]));
    store<Scalar>(at(2, 0, c), A.a2 * (A.q0 * A.n[c]) - A.a0 * (A.n * A.q2[c]));
    store<Scalar>(at(0, 2, c), A.a2 * (A.n * A.q0[c]) - A.a0 * (A.q2 * A.n[c]));
    // H13 = P~_10 - Q~_1 (erratum 2: omega~), H23 = P~_20 - Q~_2, and their mirrors
    store<Scalar>(at(1, 3, c), B.a1 * (B.q0 * B.n[c]) - B.a0 * (B.n * B.q1[c]));
    store<Scalar>(at(3, 1, c), B.a1 * (B.n * B.q0[c]) - B.a0 * (B.q1 * B.n[c]));
    store<Scalar>(at(2, 3, c), B.a2 * (B.q0 * B.n[c]) - B.a0 * (B.n * B.q2[c]));
    store<Scalar>(at(3, 2, c), B.a2 * (B.n * B.q0[c]) - B.a0 * (B.q2 * B.n[c]));
    store<Scalar>(at(0, 3, c), zero);  // H03 = 0
    store<Scalar>(at(3, 0, c), zero);
  }
}

// a times 2^k, lane by lane: exact but where a result is subnormal.
template <class W>
HINGE_FAST_INLINE void scale_by_power_of_two(W& a, int k) {
  using std::ldexp;  // QD's for dd and qd
  for (int l = 0; l < 2; ++l) {
    if constexpr (std::is_same_v<W, DD2>) {
      a.hi[l] = ldexp(a.hi[l], k);
      a.lo[l] = ldexp(a.lo[l], k);
    } else {
      a[l] = ldexp(a[l], k);
    }
  }
}

// Lane 0 plus `sign` times lane 1 of a wide value, rounded to Scalar once (for n - n~ and n + n~).
template <class Scalar, class W>
HINGE_FAST_INLINE Scalar lanes_combined(const W& a, double sign) {
  if constexpr (std::is_same_v<W, DD2>) {
    const DoubleDoubleOf<double> s = two_sum(a.hi[0], sign * a.hi[1]);
    const double low = s.lo + (a.lo[0] + sign * a.lo[1]);
    return static_cast<Scalar>(static_cast<Scalar>(s.hi) + static_cast<Scalar>(low));
  } else {
    return static_cast<Scalar>(sign > 0 ? a[0] + a[1] : a[0] - a[1]);
  }
}

// Lane l of a wide value in Scalar (DD2: hi + lo).
template <class Scalar, class W>
HINGE_FAST_INLINE Scalar lane_value(const W& a, int l) {
  if constexpr (std::is_same_v<W, DD2>)
    return static_cast<Scalar>(static_cast<Scalar>(a.hi[l]) + static_cast<Scalar>(a.lo[l]));
  else return static_cast<Scalar>(a[l]);
}

// The types whose nearly flat theta comes from the exact hinge determinant (hinge_kernel below): those of
// at most 113 bits, whose normals' difference, absolute error a few units of their precision, would cost
// theta that many units divided by theta.
template <class Scalar>
inline constexpr bool kNearFlatFromDeterminant = std::is_same_v<Scalar, long double> || std::is_same_v<Scalar, dd> ||
#if HINGE_HAVE_FLOAT128
                                                 std::is_same_v<Scalar, float128> ||
#endif
                                                 std::is_same_v<Scalar, bin128>;

// 2^-2m for a normal m = M in [2^m, 2^(m+1)) with |m| <= 500 (exact, from the exponent bits).
HINGE_FAST_INLINE double inverse_square_power_of_two(double M) {
  const std::uint64_t biased = (std::bit_cast<std::uint64_t>(M) >> 52) & 0x7ff;  // m + 1023
  const double P = std::bit_cast<double>((2046 - biased) << 52);                 // 2^-m
  return P * P;
}

// --- the wide-range fallback ----------------------------------------------------------------------

// long double (x87 extended on x86-64: 64 significand bits, exponents down to 2^-16382) holds every
// intermediate of the kernel for any hinge of doubles: differences lie in [2^-1074, 2^1025], products of
// up to six of them (or their inverses) within 2^+-6500.
static_assert(std::numeric_limits<long double>::digits >= 64 && std::numeric_limits<long double>::max_exponent >= 16384,
              "wide_range_kernel needs an extended long double");

// The sum of `count` long doubles (count <= 12) with an error below one unit in the last place of the
// result: the exact sum as a nonoverlapping expansion (Shewchuk 1997, "Adaptive precision floating-point
// arithmetic and fast robust geometric predicates": Grow-Expansion with zero elimination), then Compress,
// whose largest component approximates the whole expansion within an ulp of itself.
inline long double sum_exactly(const long double* terms, int count) {
  long double e[12];  // increasing magnitude, nonoverlapping
  int m = 0;
  for (int t = 0; t < count; ++t) {
    long double q = terms[t];
    int kept = 0;
    for (int i = 0; i < m; ++i) {
      const DoubleDoubleOf<long double> s = two_sum(q, e[i]);
      if (s.lo != 0) e[kept++] = s.lo;
      q = s.hi;
    }
    if (q != 0) e[kept++] = q;
    m = kept;
  }
  if (m == 0) return 0;
  long double g[12];
  int bottom = m - 1;
  long double q = e[m - 1];
  for (int i = m - 2; i >= 0; --i) {
    const DoubleDoubleOf<long double> s = fast_two_sum(q, e[i]);
    if (s.lo != 0) {
      g[bottom--] = s.hi;
      q = s.lo;
    } else {
      q = s.hi;
    }
  }
  g[bottom] = q;
  for (int i = bottom + 1; i < m; ++i) q = fast_two_sum(g[i], q).hi;
  return q;
}

// The cross products C of triangles() (lane 0: (x1 - x0) x (x2 - x0) = N; lane 1: (x1 - x3) x (x2 - x3) =
// -Nt) exactly, rounded to long double (relative error below 2^-63 per component): (b - a) x (c - a) = a x b
// + b x c + c x a, each component six products of input doubles, each product split exactly into two
// long doubles (fma), the twelve summed exactly. Used where the edges themselves are not exact in long
// double and a needle's cross product of rounded edges could lose every digit (even vanish).
inline Vec<Pair<long double>> exact_cross(const std::array<double, 12>& x) {
  Vec<Pair<long double>> C;
  for (int lane = 0; lane < 2; ++lane) {
    const double* a = lane == 0 ? &x[0] : &x[9];
    const double* b = &x[3];
    const double* c = &x[6];
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double factors[6][2] = {{a[i], b[j]},  {-a[j], b[i]}, {b[i], c[j]},
                                    {-b[j], c[i]}, {c[i], a[j]},  {-c[j], a[i]}};
      long double terms[12];
      for (int t = 0; t < 6; ++t) {
        const long double u = factors[t][0], v = factors[t][1];
        terms[2 * t] = u * v;
        terms[2 * t + 1] = std::fma(u, v, -terms[2 * t]);  // exact: 53 + 53 bits fit in two long doubles
      }
      C[k][lane] = sum_exactly(terms, 12);
    }
  }
  return C;
}

template <class Scalar>
void wide_range_kernel(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<Scalar>& out);

// --- the kernel ------------------------------------------------------------------------------------

// The whole kernel: theta, tan(theta/2), the branch-cut flag, grad and (if asked) hess into `out`.
// `kExactCross` (long double only): the normals from exact_cross (wide_range_kernel).
template <class Scalar, bool kExactCross = false>
HINGE_FAST_INLINE void hinge_kernel(const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<Scalar>& out) {
  using W = std::conditional_t<kExactCross, Pair<long double>, Wide<Scalar>>;
  constexpr bool kRanged = kDoubleRange<W>;
  static_assert(!kExactCross || std::is_same_v<W, Pair<long double>>);
  double probe = 0;  // NaN when a coordinate is not finite
  for (double c : x) probe += c * 0.0;
  if (probe != 0) check_finite(x);  // throws, naming the coordinate
  if (x[3] == x[6] && x[4] == x[7] && x[5] == x[8]) throw_zero_hinge_edge();

  // Lane 0: the upper triangle's edges e0, e1 = x0 - x2, e2 = x1 - x0; lane 1: the lower triangle's
  // e0, e~1 = x3 - x2, e~2 = x1 - x3 (the paper's labels (x3, x1, x2)).
  auto edges = [](const std::array<double, 12>& y, Vec<W>& f0, Vec<W>& f1, Vec<W>& f2) {
    for (int c = 0; c < 3; ++c) {
      f0[c] = difference<W>(y[6 + c], y[3 + c], y[6 + c], y[3 + c]);
      f1[c] = difference<W>(y[c], y[6 + c], y[9 + c], y[6 + c]);
      f2[c] = difference<W>(y[3 + c], y[c], y[3 + c], y[9 + c]);
    }
  };
  Vec<W> f0, f1, f2;
  edges(x, f0, f1, f2);
  int exponent = 0;
  double P2 = 1;  // 2^-2m, 2^m <= M < 2^(m+1) (triangles())
  if constexpr (kRanged || QdScalar<Scalar>) {
    auto largest_component = [&f0, &f1, &f2] {  // M (infinite when a difference overflowed)
      double m = 0;
      for (int c = 0; c < 3; ++c)
        for (int l = 0; l < 2; ++l)
          m = std::max(
              {m, std::fabs(high_part(f0[c], l)), std::fabs(high_part(f1[c], l)), std::fabs(high_part(f2[c], l))});
      return m;
    };
    // The edges are brought to M in [1, 2) by a power of two 2^-p: exact but for low parts that become
    // subnormal (2^-1000 of M at most), and then the same numbers whatever the input's scale. theta is
    // scale-invariant, grad theta scales as 2^-p and Hess theta as 2^-2p: undone exactly at the end. double
    // and float do so outside [2^-200, 2^200], the range for which triangles() states its bounds; dd and qd,
    // whose exponent range is double's and whose products of up to six edge components would overflow or
    // underflow far from 1 (and QD's atan2 fail on the result), always. When a difference overflowed, the
    // coordinates are quartered first (exact but for subnormal coordinates).
    double largest = largest_component();
    if (QdScalar<Scalar> || !(largest <= 0x1p200 && largest >= 0x1p-200)) [[unlikely]] {
      if (!(largest <= std::numeric_limits<double>::max())) {
        std::array<double, 12> quarter;
        for (int i = 0; i < 12; ++i) quarter[i] = x[i] * 0x1p-4;
        edges(quarter, f0, f1, f2);
        exponent = 4;
        largest = largest_component();
      }
      const int shift = std::ilogb(largest);  // largest > 0: x1 != x2
      for (int c = 0; c < 3; ++c) {
        scale_by_power_of_two(f0[c], -shift);
        scale_by_power_of_two(f1[c], -shift);
        scale_by_power_of_two(f2[c], -shift);
      }
      exponent += shift;
      largest = largest_component();  // in [1, 2)
    }
    if constexpr (kRanged) P2 = inverse_square_power_of_two(largest);
  }

  Vec<W> C;  // 2A n (upper), -2A~ n~ (lower): with the hinge edge, f2 x f0 = f1 x f2
  if constexpr (kExactCross) C = exact_cross(x);
  else C = cross(f2, f0);
  const W L0 = dot(f0, f0), S = dot(C, C);  // l_0^2, (2A)^2
  // When in_range() fails, the results below are replaced at the end by wide_range_kernel's (after the
  // same validity checks; calling it here, with the kernel's values live, made the common path spill).
  [[maybe_unused]] const bool fast_range = in_range(L0, S, P2);
  HingeTriangle<Scalar> T, U;
  Vec<W> nw;
  triangles<Scalar>(f0, f1, f2, C, L0, S, T, U, nw);
  for (int k = 0; k < 3; ++k) U.n[k] = -U.n[k];  // n~ = -C~ / |C~|: the lower labels run clockwise
  check_areas(x);                                // exactly (hinge_checks.hpp)

  // theta = sgn 2 atan2(|n - n~|, |n + n~|) (Fig. 3 and eq. (12)), the sign decided exactly; with n~ the
  // negated lane 1, n - n~ and n + n~ are the sum and difference of the two lanes.
  // The filter takes fl(x2 - x1), fl(x0 - x1), fl(x3 - x1): the high parts of the unscaled edges in
  // double-double and float's lanes, else rounded once from the doubles (a difference rounded to a wider
  // type first and then to double could be off by an ulp; scaled edges could have lost subnormal bits).
  double p[3], q[3], r[3];
  for (int k = 0; k < 3; ++k) {
    if (kRanged && exponent == 0) {
      p[k] = high_part(f0[k], 0);
      q[k] = -high_part(f2[k], 0);
      r[k] = -high_part(f2[k], 1);
    } else {
      p[k] = x[6 + k] - x[3 + k];
      q[k] = x[k] - x[3 + k];
      r[k] = x[9 + k] - x[3 + k];
    }
  }
  const int sign = orientation(x, p, q, r);
  Vec<Scalar> minus, plus;
  for (int k = 0; k < 3; ++k) {
    minus[k] = lanes_combined<Scalar>(nw[k], 1);
    plus[k] = lanes_combined<Scalar>(nw[k], -1);
  }
  using std::atan2;
  using std::sqrt;
  const Scalar s_minus = sqrt(minus[0] * minus[0] + minus[1] * minus[1] + minus[2] * minus[2]);  // 2 sin(theta/2)
  const Scalar s_plus = sqrt(plus[0] * plus[0] + plus[1] * plus[1] + plus[2] * plus[2]);         // 2 cos(theta/2)
  if (sign == 0) {  // coplanar: theta is 0 or pi exactly
    const bool folded = T.n[0] * U.n[0] + T.n[1] * U.n[1] + T.n[2] * U.n[2] < 0;
    out.on_branch_cut = folded;
    out.theta = folded ? pi_of<Scalar>() : Scalar(0);
    out.tan_half_theta = folded ? Scalar(std::numeric_limits<Scalar>::infinity()) : Scalar(0);
  } else {
    out.on_branch_cut = false;
    Scalar t = 2 * atan2(s_minus, s_plus);
    // Nearly flat (|theta| < 2^-20): |n - n~| is theta itself, and the normals' absolute error of a few
    // units of the type's precision is 1/theta times that relative (long double lost 312 units of 2^-53, dd
    // 949, at theta ~ 1e-19): sin theta = |D| l_0 / (|N| |N~|) with D exact (faithful_theta.hpp).
    if constexpr (kNearFlatFromDeterminant<Scalar> && !kExactCross)
      if (s_minus < Scalar(0x1p-20)) [[unlikely]] {
        using std::abs;
        using std::ldexp;
        const ScaledDeterminant D = exact_hinge_determinant(x, exponent);
        const Scalar sine =
            ldexp(abs(Scalar(Scalar(Scalar(D.hi) + Scalar(D.mid)) + Scalar(D.lo))), static_cast<int>(D.e)) *
            sqrt(lane_value<Scalar>(L0, 0)) / (sqrt(lane_value<Scalar>(S, 0)) * sqrt(lane_value<Scalar>(S, 1)));
        t = atan2(sine, Scalar(1 - s_minus * s_minus / 2));
      }
    out.theta = sign < 0 ? Scalar(-t) : t;
    const Scalar tan_half = s_minus / s_plus;  // eq. (12)
    out.tan_half_theta = sign < 0 ? Scalar(-tan_half) : tan_half;
  }

  for (int k = 0; k < 3; ++k) {  // eq. (4)
    out.grad[k] = -T.a[0] * T.n[k];
    out.grad[3 + k] = T.a[1] * T.n[k] + U.a[1] * U.n[k];
    out.grad[6 + k] = T.a[2] * T.n[k] + U.a[2] * U.n[k];
    out.grad[9 + k] = -U.a[0] * U.n[k];
  }
  if (want_hessian) hessian(T, U, out.hess.data());
  else out.hess.setZero();
  if (exponent != 0) {
    using std::ldexp;
    for (int i = 0; i < 12; ++i) out.grad[i] = ldexp(out.grad[i], -exponent);
    if (want_hessian)
      for (int i = 0; i < 144; ++i) out.hess.data()[i] = ldexp(out.hess.data()[i], -2 * exponent);
  }
  if constexpr (kRanged)
    if (!fast_range) [[unlikely]]
      wide_range_kernel(x, want_hessian, out);  // the same checks passed above
}

// The results of a long double evaluation `w` rounded to Scalar once, into `out` (on the branch cut theta
// is set as the kernel sets it, not pi rounded twice).
template <class Scalar>
void round_into(const HingeDerivatives<long double>& w, HingeDerivatives<Scalar>& out) {
  out.on_branch_cut = w.on_branch_cut;
  if (w.on_branch_cut) {
    out.theta = pi_of<Scalar>();
    out.tan_half_theta = std::numeric_limits<Scalar>::infinity();
  } else {
    out.theta = static_cast<Scalar>(w.theta);
    out.tan_half_theta = static_cast<Scalar>(w.tan_half_theta);
  }
  out.grad = w.grad.template cast<Scalar>();
  out.hess = w.hess.template cast<Scalar>();
}

// The fallback of the double and float kernels for hinges outside in_range(): the kernel in long
// double with the normals' cross products exact (exact_cross; the other quantities from the edges rounded
// to long double: relative errors ~2^-64 each, no cancellation beyond the problem's own), every result
// rounded to Scalar once. Not inlined: it is rare, and large.
template <class Scalar>
[[gnu::noinline]] void wide_range_kernel(const std::array<double, 12>& x, bool want_hessian,
                                         HingeDerivatives<Scalar>& out) {
  HingeDerivatives<long double> w;
  hinge_kernel<long double, true>(x, want_hessian, w);
  round_into(w, out);
}

}  // namespace detail
}  // namespace hinge::fast
