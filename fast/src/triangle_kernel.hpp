// fast/src/triangle_kernel.hpp: one triangle of Algorithm 2 (lines 8-19): its geometry, the local
// triangle Hessian H^D of eq. (7) with the conditional transpose, and the per-edge terms of the hinges it
// owns (grad theta, eq. (4); the force, eq. (2); psi'' grad theta grad theta^T, section 4.2).
//
//                 x_0                 a face (x_0, x_1, x_2) in the mesh's counter-clockwise order
//          e_1   /   \   e_2          e_i = x_{i+2} - x_{i+1}, opposite x_i, l_i = |e_i|
//               /  T  \               alpha_i angle at x_i, h_i altitude from x_i, m_i = ê_i x n the
//            x_1 -----> x_2           outward unit normal of e_i in the plane, n = N / |N|,
//                 e_0                 N = (x_1 - x_0) x (x_2 - x_0) = e_1 x e_2 = 2A n
//
// Indices are taken mod 3. Local blocks: diag[i] = H^D_ii, off[i] = H^D_{i,i+1} (rows x_i, columns
// x_{i+1}); the others follow from H^D_ji = (H^D_ij)^T. Variables of the face: x_0, x_1, x_2 (9).
//
// Eq. (7), with c_i = sigma_i psi'_i (sigma_i = 1 for an interior edge i, else 0):
//   d_i = c_{i-1} cos(alpha_{i+1}) + c_{i+1} cos(alpha_{i-1}) - c_i,   omega_ij = 1 / (h_i h_j),
//   M_i = n m_i^T,  N_i = M_i / l_i^2,  R_i = c_i N_i,
//   H^D_ii      = omega_ii d_i (M_i^T + M_i) - R_{i+1} - R_{i+2}
//   H^D_{i,i+1} = omega_{i,i+1} (d_i M_{i+1}^T + d_{i+1} M_i) + R_{i+2}^dagger
// R_{i+2} belongs to the block of the two vertices of edge i+2 (x_i, x_{i+1}): a face computing its own
// half-hinge of edge k in its counter-clockwise labels puts + c_k N_k, untransposed, in block
// (x_{k+1}, x_{k+2}); the two faces of an edge see it in opposite directions, and N_k + N~_k is symmetric
// (proofs/half-hinge.md), so the mesh sum is right when exactly one of them transposes (the dagger). Which
// one is the EdgeOrientation of pattern.hpp: the face that owns the edge. H^D_ii itself is not
// symmetric (R_i is not), but the mesh sum of every diagonal block is; only upper triangles are stored.
// Errata (proofs/errata.md) used here: cos(alpha_i) = -ê_{i+1} . ê_{i+2} (Alg. 2, line 9, with cyclically
// oriented edges), and d_i carries the cosine of the other hinge vertex (eq. (5)'s P_ij corrected).
//
// Per owned interior edge k, with p = x_k, q = x_{k+1}, r = x_{k+2} and s the far vertex of the face T~
// across the edge (n~, A~ its normal and area):
//   grad_p theta = -(l_k / 2A) n                       = -n / h_k                               eq. (4)
//   grad_q theta = -(e_k . e_{k+1}) / (l_k 2A) n + (e_k . (r - s)) / (l_k 2A~) n~
//   grad_r theta = -(e_k . e_{k+2}) / (l_k 2A) n + (e_k . (s - q)) / (l_k 2A~) n~
//   grad_s theta = -(l_k / 2A~) n~                     = -n~ / h~_s
// (the coefficients are eq. (4)'s cos(alpha) / h written with dot products: cos(alpha_{k+2}) / h_{k+1} =
// -(e_k . e_{k+1}) / (l_k 2A), and on T~ alike, which needs no lengths of T~.)
//
// Range: plain Scalar arithmetic on the vertices, with no rescaling (the mesh's usable size is bounded by
// the squared lengths here and by the face pass's (2A)^2, assemble.hpp). Every intermediate scales like a
// length to a power between -2 and 2 (l^2, e . e', 1/l, l/2A, 1/l^2, 1/(h_i h_j), the last two the
// results' own scale), never 1/(l 2A) or 1/l^3, which could overflow where the results do not. The
// products e_i . e_j are dot products of the edges (no law of cosines, which cancels on short edges).
#pragma once

#include <array>
#include <cmath>

#include "columns.hpp"
#include "exact.hpp"

namespace hinge::fast {

template <class Scalar>
using Vec3 = std::array<Scalar, 3>;
template <class Scalar>
using Block3 = std::array<std::array<Scalar, 3>, 3>;  // [row][column]
// A 3 x 3 block as its three columns (columns.hpp): the form the kernels compute and scatter.
template <class Scalar>
using Columns3 = std::array<Column<Scalar>, 3>;

// Algorithm 2, lines 8-11, from the three vertices and the face's unit normal and inverse double area
// (computed once per face before the edge loop, since theta needs them: Algorithm 2, line 4).
template <class Scalar>
struct TriangleGeometry {
  std::array<Vec3<Scalar>, 3> e;    // e_i
  std::array<Scalar, 3> L;          // l_i^2
  std::array<Scalar, 3> inv_l;      // 1 / l_i                                     (line 2)
  std::array<Scalar, 3> G;          // e_{i+1} . e_{i+2}
  std::array<Scalar, 3> cos_alpha;  // -ê_{i+1} . ê_{i+2}                           (line 9, erratum)
  std::array<Scalar, 3> inv_h;      // 1 / h_i = l_i / 2A                           (line 10)
  std::array<Vec3<Scalar>, 3> m;    // ê_i x n                                      (line 11)
  Vec3<Scalar> n;
  Scalar inv_double_area;  // 1 / 2A                                       (line 8)
};

// The next and the previous local index mod 3, without a division (for an edge k known only at run
// time: the owned edges of a face).
HINGE_FAST_INLINE constexpr int next3(int k) { return k == 2 ? 0 : k + 1; }
HINGE_FAST_INLINE constexpr int prev3(int k) { return k == 0 ? 2 : k - 1; }

template <class Scalar>
HINGE_FAST_INLINE Vec3<Scalar> vsub(const Vec3<Scalar>& a, const Vec3<Scalar>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
template <class Scalar>
HINGE_FAST_INLINE Scalar vdot(const Vec3<Scalar>& a, const Vec3<Scalar>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class Scalar>
HINGE_FAST_INLINE void triangle_geometry(const Vec3<Scalar>& x0, const Vec3<Scalar>& x1, const Vec3<Scalar>& x2,
                                         const Vec3<Scalar>& n, const Scalar& inv_double_area,
                                         TriangleGeometry<Scalar>& t) {
  using std::sqrt;
  t.n = n;
  t.inv_double_area = inv_double_area;
  t.e = {vsub(x2, x1), vsub(x0, x2), vsub(x1, x0)};
  HINGE_FAST_UNROLL
  for (int i = 0; i < 3; ++i) {
    t.L[i] = vdot(t.e[i], t.e[i]);
    const Scalar l = sqrt(t.L[i]);
    t.inv_l[i] = Scalar(1) / l;
    t.inv_h[i] = l * inv_double_area;
    const auto& e = t.e[i];
    t.m[i] = {(e[1] * n[2] - e[2] * n[1]) * t.inv_l[i], (e[2] * n[0] - e[0] * n[2]) * t.inv_l[i],
              (e[0] * n[1] - e[1] * n[0]) * t.inv_l[i]};
  }
  HINGE_FAST_UNROLL
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    t.G[i] = vdot(t.e[j], t.e[k]);
    t.cos_alpha[i] = -(t.G[i] * t.inv_l[j]) * t.inv_l[k];
  }
}

// Eq. (7): the local triangle Hessian, column by column. `c[i]` = sigma_i psi'_i; bit i of `dagger` set:
// transpose R_i; bit i of `mirror` set: return off[i] as H^D_{i+1,i} = (H^D_{i,i+1})^T (the form in which
// the assembly stores it when x_{i+1} has the smaller index). Only the upper triangles of the diagonal
// blocks are meaningful (the only part the assembly stores). Column c of M_i = n m_i^T is n m_i[c], of
// M_i^T it is m_i n[c].
template <class Scalar>
HINGE_FAST_INLINE void triangle_hessian(const TriangleGeometry<Scalar>& t, const std::array<Scalar, 3>& c,
                                        unsigned dagger, unsigned mirror, std::array<Columns3<Scalar>, 3>& diag,
                                        std::array<Columns3<Scalar>, 3>& off) {
  std::array<Scalar, 3> d, rc;
  HINGE_FAST_UNROLL
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    d[i] = c[k] * t.cos_alpha[j] + c[j] * t.cos_alpha[k] - c[i];  // eq. (7), d_i
    rc[i] = c[i] * (t.inv_l[i] * t.inv_l[i]);                     // R_i = rc_i M_i
  }
  const Column<Scalar> n = column(t.n);
  const std::array<Column<Scalar>, 3> m{column(t.m[0]), column(t.m[1]), column(t.m[2])};
  HINGE_FAST_UNROLL
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const Scalar w_ii = t.inv_h[i] * t.inv_h[i] * d[i];  // omega_ii d_i
    const Scalar w_i = t.inv_h[i] * t.inv_h[j];          // omega_{i,i+1}
    const Scalar wd_i = w_i * d[i], wd_j = w_i * d[j];
    const bool transpose = (dagger >> k) & 1u, mirrored = (mirror >> i) & 1u;
    HINGE_FAST_UNROLL
    for (int s = 0; s < 3; ++s) {
      // H^D_ii = omega_ii d_i (M_i^T + M_i) - R_{i+1} - R_{i+2}
      diag[i][s] = w_ii * (m[i] * t.n[s] + n * t.m[i][s]) - rc[j] * (n * t.m[j][s]) - rc[k] * (n * t.m[k][s]);
      // H^D_{i,i+1} = omega_{i,i+1} (d_i M_{i+1}^T + d_{i+1} M_i) + R_{i+2}^dagger, or its transpose
      if (!mirrored)
        off[i][s] =
            wd_i * (m[j] * t.n[s]) + wd_j * (n * t.m[i][s]) + rc[k] * (transpose ? m[k] * t.n[s] : n * t.m[k][s]);
      else
        off[i][s] =
            wd_i * (n * t.m[j][s]) + wd_j * (m[i] * t.n[s]) + rc[k] * (transpose ? n * t.m[k][s] : m[k] * t.n[s]);
    }
  }
}

// The hinge of the face's local edge k seen from the face that owns it: grad theta (eq. (4)) at p, q, r,
// s. `nt`, `inv_double_area_t`: normal and 1 / 2A~ of the face across; `xs`: its far vertex s;
// `xq`, `xr`: the vertices q = x_{k+1}, r = x_{k+2}.
template <class Scalar>
HINGE_FAST_INLINE void hinge_gradient(const TriangleGeometry<Scalar>& t, int k, const Vec3<Scalar>& xq,
                                      const Vec3<Scalar>& xr, const Vec3<Scalar>& xs, const Vec3<Scalar>& nt,
                                      const Scalar& inv_double_area_t, std::array<Vec3<Scalar>, 4>& g) {
  const int j = next3(k), i = prev3(k);
  const auto& ek = t.e[k];
  // Each coefficient is (a dot product with e_k) / l_k, then / 2A: the intermediates scale like lengths,
  // never 1 / (l_k 2A) (which overflows for a short edge or a small triangle whose 1 / h does not).
  const Scalar il = t.inv_l[k], lk = t.L[k] * il;  // 1 / l_k, l_k
  const Scalar gp = -t.inv_h[k];                   // l_k / 2A
  const Scalar gq = -((t.G[i] * il) * t.inv_double_area),
               gr = -((t.G[j] * il) * t.inv_double_area);  // G_i = e_k . e_{k+1}, G_j = e_k . e_{k+2}
  const Scalar tq = (vdot(ek, vsub(xr, xs)) * il) * inv_double_area_t,
               tr = (vdot(ek, vsub(xs, xq)) * il) * inv_double_area_t;
  const Scalar ts = -(lk * inv_double_area_t);
  for (int c = 0; c < 3; ++c) {
    g[0][c] = gp * t.n[c];               // p
    g[1][c] = gq * t.n[c] + tq * nt[c];  // q
    g[2][c] = gr * t.n[c] + tr * nt[c];  // r
    g[3][c] = ts * nt[c];                // s
  }
}

// psi'' grad theta grad theta^T of the owned hinge of edge k into the local blocks of p, q, r (section 4.2:
// the blocks among the face's own vertices join H^D before the assembly). `pg[a]` = psi'' g[a]; column c
// of psi'' g_a g_b^T is pg[a] g_b[c]. `mirror` as for triangle_hessian.
template <class Scalar>
HINGE_FAST_INLINE void add_hinge_outer_product(int k, const std::array<Column<Scalar>, 4>& pg,
                                               const std::array<Vec3<Scalar>, 4>& g, unsigned mirror,
                                               std::array<Columns3<Scalar>, 3>& diag,
                                               std::array<Columns3<Scalar>, 3>& off) {
  const int j = next3(k), i = prev3(k);
  // local vertex k, k+1, k+2 is hinge vertex p (0), q (1), r (2); off[k] joins p, q, off[j] q, r, off[i] r, p
  const int first[3] = {0, 1, 2}, second[3] = {1, 2, 0};
  const int block[3] = {k, j, i};
  HINGE_FAST_UNROLL
  for (int b = 0; b < 3; ++b) {
    const int a = first[b], z = second[b], o = block[b];
    HINGE_FAST_UNROLL
    for (int s = 0; s < 3; ++s) {
      diag[o][s] += pg[a] * g[a][s];
      off[o][s] += ((mirror >> o) & 1u) ? pg[z] * g[a][s] : pg[a] * g[z][s];
    }
  }
}

}  // namespace hinge::fast
