// The exact stage of the certified oracle (hinge/oracle/exact.hpp): integer edge vectors, normals, and
// eqs. (4)-(6) over a common denominator. The rewriting is derived in oracle/README.md; in short, with
// l_i = |e_i|, |N| = 2A, h_i = |N| / l_i, m_i = (e_i x N) / (l_i |N|) (outward, upper triangle) and
// cos(alpha_i) = -(e_{i+1} . e_{i+2}) / (l_{i+1} l_{i+2}), every building block of eq. (5) is an exact
// rational times 1/l0 (l0 = |e0|, shared by both triangles):
//
//   omega_ij M_j = Q_j = s N W_j^T / (nn^2 l0)                 W_j = e_j x N (upper), Nt x e~_j (lower)
//   P_ij = omega_ij cos(alpha_{3-i}) M_j^T = -d_i W_j N^T / (nn^2 l0),  d_i = e0 . e_i   (erratum 1)
//   N_0 = M_0 / l0^2 = N W_0^T / (nn s l0)
//
// and eq. (4) is grad_x0 = -s N / (nn l0), grad_x1 = -(d1 N / nn + d~1 Nt / tt) / l0, etc.
#include "hinge/oracle/exact.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "hinge/reference/errors.hpp"
#include "hinge/reference/hinge_checks.hpp"

namespace hinge::oracle {
namespace {

using V3 = std::array<Int, 3>;
using M3 = std::array<Int, 9>;  // row-major 3x3

V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 neg(const V3& a) { return {-a[0], -a[1], -a[2]}; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Int dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero(const V3& a) { return sgn(a[0]) == 0 && sgn(a[1]) == 0 && sgn(a[2]) == 0; }

M3 outer(const V3& a, const V3& b) {  // a b^T
  M3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[3 * r + c] = a[r] * b[c];
  return m;
}
M3 transpose(const M3& a) {
  M3 t;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) t[3 * r + c] = a[3 * c + r];
  return t;
}
M3 S(const M3& a) {  // eq. (5): S(A) = A + A^T
  M3 s;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) s[3 * r + c] = a[3 * r + c] + a[3 * c + r];
  return s;
}
M3 lin(const Int& a, const M3& A, const Int& b, const M3& B) {  // a A + b B
  M3 m;
  for (int k = 0; k < 9; ++k) m[k] = a * A[k] + b * B[k];
  return m;
}
M3 scaled(const Int& a, const M3& A) {
  M3 m;
  for (int k = 0; k < 9; ++k) m[k] = a * A[k];
  return m;
}
M3 plus(const M3& A, const M3& B) {
  M3 m;
  for (int k = 0; k < 9; ++k) m[k] = A[k] + B[k];
  return m;
}
M3 minus(const M3& A, const M3& B) {
  M3 m;
  for (int k = 0; k < 9; ++k) m[k] = A[k] - B[k];
  return m;
}

V3 vertex(const ScaledHinge& x, int v) { return {x.X[3 * v], x.X[3 * v + 1], x.X[3 * v + 2]}; }

}  // namespace

ScaledHinge scale_exactly(const std::array<double, 12>& x) {
  // x = m 2^e with an integer |m| < 2^53; then X = m 2^(e - e_min), F = -e_min.
  std::array<long, 12> mantissa{}, exponent{};
  long e_min = LONG_MAX;
  for (int i = 0; i < 12; ++i) {
    if (!std::isfinite(x[i])) check_finite(x);  // throws, naming the first non-finite coordinate
    if (x[i] == 0) continue;
    int e = 0;
    const double f = std::frexp(x[i], &e);  // x = f 2^e, 0.5 <= |f| < 1
    mantissa[i] = static_cast<long>(std::ldexp(f, 53));
    exponent[i] = e - 53;
    e_min = std::min(e_min, exponent[i]);
  }
  if (e_min == LONG_MAX) e_min = 0;
  ScaledHinge h;
  h.F = -e_min;
  for (int i = 0; i < 12; ++i) {
    h.X[i] = mantissa[i];
    if (mantissa[i] != 0) h.X[i] <<= static_cast<mp_bitcnt_t>(exponent[i] - e_min);
  }
  return h;
}

ScaledHinge refine(const ScaledHinge& h, unsigned long extra) {
  ScaledHinge r = h;
  for (auto& v : r.X) v <<= extra;
  r.F += static_cast<long>(extra);
  return r;
}

std::size_t ExactHinge::max_bits() const {
  std::size_t bits = 0;
  auto see = [&bits](const Int& v) { bits = std::max(bits, mpz_sizeinbase(v.get_mpz_t(), 2)); };
  for (const Int* v : {&s, &nn, &tt, &X, &Y, &g_den, &h_den}) see(*v);
  for (const auto& v : g) see(v);
  if (has_hessian)
    for (const auto& v : h) see(v);
  return bits;
}

ExactHinge exact_hinge(const std::array<double, 12>& x, bool with_hessian) {
  return exact_hinge(scale_exactly(x), with_hessian);
}

ExactHinge exact_hinge(const ScaledHinge& x, bool with_hessian) {
  const V3 x0 = vertex(x, 0), x1 = vertex(x, 1), x2 = vertex(x, 2), x3 = vertex(x, 3);
  const V3 e0 = sub(x2, x1), e1 = sub(x0, x2), e2 = sub(x1, x0);  // Fig. 1, upper triangle
  const V3 et1 = sub(x3, x2), et2 = sub(x1, x3);                   // lower triangle: e~1, e~2
  if (is_zero(e0)) throw_zero_hinge_edge();
  const V3 N = cross(e2, neg(e1));    // (x1 - x0) x (x2 - x0)
  const V3 Nt = cross(neg(et1), et2);  // (x2 - x3) x (x1 - x3)
  ExactHinge r;
  r.F = x.F;
  r.nn = dot(N, N);
  r.tt = dot(Nt, Nt);
  if (sgn(r.nn) == 0) throw_zero_area(true);
  if (sgn(r.tt) == 0) throw_zero_area(false);
  const Int& nn = r.nn;
  const Int& tt = r.tt;
  r.s = dot(e0, e0);
  const Int& s = r.s;
  r.X = dot(N, Nt);              // |N| |Nt| cos(theta)
  r.Y = dot(cross(N, Nt), e0);   // |N| |Nt| |e0| sin(theta): the sign of theta (docs/contract.md)

  // d_i = e0 . e_i: l_i cos(alpha_{3-i}) = -d_i / l0 (upper), the same with e~_i (lower).
  const Int d1 = dot(e0, e1), d2 = dot(e0, e2), dt1 = dot(e0, et1), dt2 = dot(e0, et2);

  // Eq. (4) over g_den = nn tt, times l0:
  //   grad_x0 = -n / h0                                -> -s N / nn
  //   grad_x1 = cos(a2)/h1 n + cos(a~2)/h~1 n~         -> -(d1 N / nn + d~1 Nt / tt)
  //   grad_x2 = cos(a1)/h2 n + cos(a~1)/h~2 n~         -> -(d2 N / nn + d~2 Nt / tt)
  //   grad_x3 = -n~ / h~0                              -> -s Nt / tt
  r.g_den = nn * tt;
  for (int c = 0; c < 3; ++c) {
    r.g[0 + c] = -(s * tt * N[c]);
    r.g[3 + c] = -(d1 * tt * N[c] + dt1 * nn * Nt[c]);
    r.g[6 + c] = -(d2 * tt * N[c] + dt2 * nn * Nt[c]);
    r.g[9 + c] = -(s * nn * Nt[c]);
  }
  if (!with_hessian) return r;

  // Eqs. (5)-(6) over h_den = 2 nn^2 tt^2 s, times l0. A block over nn^2 is multiplied by a = 2 tt^2 s,
  // one over tt^2 by b = 2 nn^2 s. W_j = e_j x N (upper: m_j = W_j / (l_j |N|)), Wt_j = Nt x e~_j
  // (lower, traversed clockwise about n~: m~_j = Wt_j / (l_j |Nt|)).
  r.has_hessian = true;
  r.h_den = 2 * nn * nn * tt * tt * s;
  const Int a = 2 * tt * tt * s, b = 2 * nn * nn * s;
  const V3 W0 = cross(e0, N), W1 = cross(e1, N), W2 = cross(e2, N);
  const V3 Wt0 = cross(Nt, e0), Wt1 = cross(Nt, et1), Wt2 = cross(Nt, et2);

  // N0 + N~0 = N W0^T / (nn s l0) + Nt Wt0^T / (tt s l0), taken by its symmetric part as the reference
  // does (it is symmetric: proofs/half-hinge.md; tests/conformance checks it exactly). Times h_den l0:
  const M3 Z = S(lin(nn * tt * tt, outer(N, W0), nn * nn * tt, outer(Nt, Wt0)));
  const M3 NW0 = outer(N, W0), NtWt0 = outer(Nt, Wt0);

  std::array<std::array<M3, 4>, 4> K;
  // H00 = -S(Q0), H33 = -S(Q~0): Q0 = s N W0^T / (nn^2 l0).
  K[0][0] = scaled(-(a * s), S(NW0));
  K[3][3] = scaled(-(b * s), S(NtWt0));
  // H11 = S(P11) + S(P~11) - (N0 + N~0): P11 = -d1 W1 N^T / (nn^2 l0) (erratum 1: cos(alpha2)).
  K[1][1] = minus(lin(-(a * d1), S(outer(W1, N)), -(b * dt1), S(outer(Wt1, Nt))), Z);
  // H22 = S(P22) + S(P~22) - (N0 + N~0): P22 = -d2 W2 N^T / (nn^2 l0) (erratum 1: cos(alpha1)).
  K[2][2] = minus(lin(-(a * d2), S(outer(W2, N)), -(b * dt2), S(outer(Wt2, Nt))), Z);
  // H10 = P10 - Q1, H20 = P20 - Q2.
  K[1][0] = lin(-(a * d1), outer(W0, N), -(a * s), outer(N, W1));
  K[2][0] = lin(-(a * d2), outer(W0, N), -(a * s), outer(N, W2));
  // H13 = P~10 - Q~1, H23 = P~20 - Q~2 (erratum 2: the lower triangle's own omega~).
  K[1][3] = lin(-(b * dt1), outer(Wt0, Nt), -(b * s), outer(Nt, Wt1));
  K[2][3] = lin(-(b * dt2), outer(Wt0, Nt), -(b * s), outer(Nt, Wt2));
  // H12 = P12 + P21^T + P~12 + P~21^T + N0 + N~0.
  K[1][2] = plus(plus(lin(-(a * d1), outer(W2, N), -(a * d2), outer(N, W1)),
                      lin(-(b * dt1), outer(Wt2, Nt), -(b * dt2), outer(Nt, Wt1))),
                 Z);
  // H03 = 0 (eq. (6)); the remaining blocks by symmetry, H_ji = H_ij^T.
  K[0][3] = M3{};
  K[3][0] = M3{};
  K[0][1] = transpose(K[1][0]);
  K[0][2] = transpose(K[2][0]);
  K[3][1] = transpose(K[1][3]);
  K[3][2] = transpose(K[2][3]);
  K[2][1] = transpose(K[1][2]);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int rr = 0; rr < 3; ++rr)
        for (int cc = 0; cc < 3; ++cc) r.h[12 * (3 * i + rr) + 3 * j + cc] = K[i][j][3 * rr + cc];
  return r;
}

}  // namespace hinge::oracle
