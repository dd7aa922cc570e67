// oracle/src/exact_form.hpp: eqs. (4)-(6) over a common denominator (private to hinge::oracle), written
// once for any ring T: exact integers (exact.cpp, T = Int) and the fast path's double-double with an
// error bound (fast_path.cpp, T = Bounded). The rewriting is derived in oracle/README.md; in short, with
// l_i = |e_i|, |N| = 2A, h_i = |N| / l_i, m_i = (e_i x N) / (l_i |N|) (outward, upper triangle) and
// cos(alpha_i) = -(e_{i+1} . e_{i+2}) / (l_{i+1} l_{i+2}), every building block of eq. (5) is an element
// of T times 1/l0 (l0 = |e0|, shared by both triangles):
//
//   omega_ij M_j = Q_j = s N W_j^T / (nn^2 l0)                 W_j = e_j x N (upper), Nt x e~_j (lower)
//   P_ij = omega_ij cos(alpha_{3-i}) M_j^T = -d_i W_j N^T / (nn^2 l0),  d_i = e0 . e_i   (erratum 1)
//   N_0 = M_0 / l0^2 = N W_0^T / (nn s l0)
//
// and eq. (4) is grad_x0 = -s N / (nn l0), grad_x1 = -(d1 N / nn + d~1 Nt / tt) / l0, etc.
#pragma once

#include <array>

namespace hinge::oracle::detail {

template <class T>
using V3 = std::array<T, 3>;
template <class T>
using M3 = std::array<T, 9>;  // row-major 3x3

// The edges of Fig. 1: e0 = x2 - x1, e1 = x0 - x2, e2 = x1 - x0 (upper), e~1 = x3 - x2, e~2 = x1 - x3.
template <class T>
struct Edges {
  V3<T> e0, e1, e2, et1, et2;
};

// What the oracle rounds: theta = atan2(Y / sqrt(s), X), grad theta = g / (g_den sqrt(s)),
// Hess theta = h / (h_den sqrt(s)) (in the units of the edges).
template <class T>
struct Form {
  T s;                  // e0 . e0
  T nn, tt;             // N . N, Nt . Nt: (2A)^2 of the upper and lower triangle
  T X, Y;               // N . Nt and (N x Nt) . e0
  std::array<T, 12> g;  // eq. (4) over g_den = nn tt
  T g_den;
  std::array<T, 144> h;  // eqs. (5)-(6) over h_den = 2 nn^2 tt^2 s, row-major
  T h_den;
};

namespace form {

template <class T>
V3<T> neg(const V3<T>& a) {
  return {-a[0], -a[1], -a[2]};
}
template <class T>
V3<T> cross(const V3<T>& a, const V3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class T>
T dot(const V3<T>& a, const V3<T>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class T>
M3<T> outer(const V3<T>& a, const V3<T>& b) {  // a b^T
  M3<T> m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m[3 * r + c] = a[r] * b[c];
  return m;
}
template <class T>
M3<T> transpose(const M3<T>& a) {
  M3<T> t;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) t[3 * r + c] = a[3 * c + r];
  return t;
}
template <class T>
M3<T> S(const M3<T>& a) {  // eq. (5): S(A) = A + A^T
  M3<T> s;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) s[3 * r + c] = a[3 * r + c] + a[3 * c + r];
  return s;
}
template <class T>
M3<T> lin(const T& a, const M3<T>& A, const T& b, const M3<T>& B) {  // a A + b B
  M3<T> m;
  for (int k = 0; k < 9; ++k) m[k] = a * A[k] + b * B[k];
  return m;
}
template <class T>
M3<T> scaled(const T& a, const M3<T>& A) {
  M3<T> m;
  for (int k = 0; k < 9; ++k) m[k] = a * A[k];
  return m;
}
template <class T>
M3<T> plus(const M3<T>& A, const M3<T>& B) {
  M3<T> m;
  for (int k = 0; k < 9; ++k) m[k] = A[k] + B[k];
  return m;
}
template <class T>
M3<T> minus(const M3<T>& A, const M3<T>& B) {
  M3<T> m;
  for (int k = 0; k < 9; ++k) m[k] = A[k] - B[k];
  return m;
}

}  // namespace form

// The normals N = (x1 - x0) x (x2 - x0) and Nt = (x2 - x3) x (x1 - x3).
template <class T>
V3<T> upper_normal(const Edges<T>& e) {
  return form::cross(e.e2, form::neg(e.e1));
}
template <class T>
V3<T> lower_normal(const Edges<T>& e) {
  return form::cross(form::neg(e.et1), e.et2);
}

// The rest of r from the edges, the normals and r.nn = N . N, r.tt = Nt . Nt (which the caller computes
// first, to check the triangles): s, X, Y, eq. (4), and eqs. (5)-(6) with `with_hessian`.
template <class T>
void fill_form(const Edges<T>& e, const V3<T>& N, const V3<T>& Nt, Form<T>& r, bool with_hessian) {
  using namespace form;
  const T& nn = r.nn;
  const T& tt = r.tt;
  r.s = dot(e.e0, e.e0);
  const T& s = r.s;
  r.X = dot(N, Nt);               // |N| |Nt| cos(theta)
  r.Y = dot(cross(N, Nt), e.e0);  // |N| |Nt| |e0| sin(theta): the sign of theta (docs/contract.md)

  // d_i = e0 . e_i: l_i cos(alpha_{3-i}) = -d_i / l0 (upper), the same with e~_i (lower).
  const T d1 = dot(e.e0, e.e1), d2 = dot(e.e0, e.e2), dt1 = dot(e.e0, e.et1), dt2 = dot(e.e0, e.et2);

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
  if (!with_hessian) return;

  // Eqs. (5)-(6) over h_den = 2 nn^2 tt^2 s, times l0. A block over nn^2 is multiplied by a = 2 tt^2 s,
  // one over tt^2 by b = 2 nn^2 s. W_j = e_j x N (upper: m_j = W_j / (l_j |N|)), Wt_j = Nt x e~_j
  // (lower, traversed clockwise about n~: m~_j = Wt_j / (l_j |Nt|)).
  const T two(2);
  r.h_den = two * nn * nn * tt * tt * s;
  const T a = two * tt * tt * s, b = two * nn * nn * s;
  const V3<T> W0 = cross(e.e0, N), W1 = cross(e.e1, N), W2 = cross(e.e2, N);
  const V3<T> Wt0 = cross(Nt, e.e0), Wt1 = cross(Nt, e.et1), Wt2 = cross(Nt, e.et2);

  // N0 + N~0 = N W0^T / (nn s l0) + Nt Wt0^T / (tt s l0), taken by its symmetric part as the reference
  // does (it is symmetric: proofs/half-hinge.md; tests/conformance checks it exactly). Times h_den l0:
  const M3<T> NW0 = outer(N, W0), NtWt0 = outer(Nt, Wt0);
  const M3<T> Z = S(lin(T(nn * tt * tt), NW0, T(nn * nn * tt), NtWt0));

  // Block (i, j) of the Hessian, and its transpose as block (j, i) (H_ji = H_ij^T).
  auto put = [&r](int i, int j, const M3<T>& m) {
    for (int rr = 0; rr < 3; ++rr)
      for (int cc = 0; cc < 3; ++cc) {
        r.h[12 * (3 * i + rr) + 3 * j + cc] = m[3 * rr + cc];
        if (i != j) r.h[12 * (3 * j + cc) + 3 * i + rr] = m[3 * rr + cc];
      }
  };
  // H00 = -S(Q0), H33 = -S(Q~0): Q0 = s N W0^T / (nn^2 l0).
  put(0, 0, scaled(T(-(a * s)), S(NW0)));
  put(3, 3, scaled(T(-(b * s)), S(NtWt0)));
  const T ad1 = -(a * d1), ad2 = -(a * d2), as = -(a * s), bdt1 = -(b * dt1), bdt2 = -(b * dt2), bs = -(b * s);
  // H11 = S(P11) + S(P~11) - (N0 + N~0): P11 = -d1 W1 N^T / (nn^2 l0) (erratum 1: cos(alpha2)).
  put(1, 1, minus(lin(ad1, S(outer(W1, N)), bdt1, S(outer(Wt1, Nt))), Z));
  // H22 = S(P22) + S(P~22) - (N0 + N~0): P22 = -d2 W2 N^T / (nn^2 l0) (erratum 1: cos(alpha1)).
  put(2, 2, minus(lin(ad2, S(outer(W2, N)), bdt2, S(outer(Wt2, Nt))), Z));
  // H10 = P10 - Q1, H20 = P20 - Q2.
  put(1, 0, lin(ad1, transpose(NW0), as, outer(N, W1)));
  put(2, 0, lin(ad2, transpose(NW0), as, outer(N, W2)));
  // H13 = P~10 - Q~1, H23 = P~20 - Q~2 (erratum 2: the lower triangle's own omega~).
  put(1, 3, lin(bdt1, transpose(NtWt0), bs, outer(Nt, Wt1)));
  put(2, 3, lin(bdt2, transpose(NtWt0), bs, outer(Nt, Wt2)));
  // H12 = P12 + P21^T + P~12 + P~21^T + N0 + N~0.
  put(1, 2, plus(plus(lin(ad1, outer(W2, N), ad2, outer(N, W1)), lin(bdt1, outer(Wt2, Nt), bdt2, outer(Nt, Wt1))), Z));
  // H03 = 0 (eq. (6)).
  put(0, 3, M3<T>{});
  // So h is exactly symmetric: h[12 p + q] and h[12 q + p] are one value.
}

}  // namespace hinge::oracle::detail
