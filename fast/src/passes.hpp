// fast/src/passes.hpp: the bodies of Algorithm 2's passes over a mesh (hinge/fast/assemble.hpp): the
// face pass (line 8: n, 1 / 2A), the bend angle of a hinge from its two faces (lines 1-4, eq. (12)), and
// the assembly pass (lines 7-21: eq. (7) with the conditional transpose, eq. (4) and eqs. (2)-(3) for the
// owned hinges, the scatter into the pattern's slots). Templated on the scalar type; for double the face
// and assembly passes are compiled per instruction set (assemble_double.cpp).
//
// Sign of theta. The filter of exact.hpp decides it for almost every hinge; when it cannot, a hinge on
// the folded side (n . n~ < 0) asks hinge_orientation_exact, so that theta = +pi exactly on the branch cut;
// a hinge on the flat side takes the sign of the computed determinant (theta is then within rounding of
// 0 and continuous there: either sign gives the same result to within that rounding).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <boost/math/constants/constants.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "columns.hpp"
#include "exact.hpp"
#include "hinge/core/energy.hpp"
#include "hinge/core/predicates.hpp"
#include "hinge/core/scalar.hpp"
#include "hinge/fast/pattern.hpp"
#include "triangle_kernel.hpp"

namespace hinge::fast::detail {

template <class Scalar>
HINGE_FAST_INLINE Vec3<Scalar> point(const Mesh& mesh, Index v) {
  const auto& p = mesh.vertices[v];
  return {from_double<Scalar>(p[0]), from_double<Scalar>(p[1]), from_double<Scalar>(p[2])};
}

// The face pass for faces [begin, end): n and 1 / 2A (Algorithm 2, line 8); flags a face whose area the
// filter cannot certify nonzero (or that is not finite) for the exact check (suspect[f] is written for
// every face: 0 or 1, so the flags need no clearing before the pass). In Scalar itself; double has its own,
// in double-double (face_pass_lanes.hpp).
template <class Scalar>
HINGE_FAST_INLINE void face_pass_body(const Mesh& mesh, const Pattern& pattern, std::size_t begin, std::size_t end,
                                      std::array<Scalar, 4>* face, char* suspect) {
  using std::sqrt;
  const auto& faces = pattern.faces();
  for (std::size_t f = begin; f < end; ++f) {
    const Pattern::Face& F = faces[f];
    if (F.highest < 0) {  // in no hinge
      suspect[f] = 0;
      continue;
    }
    const Vec3<Scalar> x0 = point<Scalar>(mesh, F.v[0]), x1 = point<Scalar>(mesh, F.v[1]),
                       x2 = point<Scalar>(mesh, F.v[2]);
    const Vec3<Scalar> a = vsub(x1, x0), b = vsub(x2, x0);
    const Vec3<Scalar> N{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const Scalar area2 = sqrt(vdot(N, N));
    const Scalar inv = Scalar(1) / area2;
    face[f] = {N[0] * inv, N[1] * inv, N[2] * inv, inv};
    // Certified nonzero when some component exceeds its error bound: 2 roundings in each difference,
    // one in each product and the subtraction: 8 units of the permanent is generous (only a flag: the
    // exact check follows).
    bool certain = false;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      using std::abs;
      const Scalar perm = abs(a[i] * b[j]) + abs(a[j] * b[i]);
      certain = certain || abs(N[k]) > 8 * std::numeric_limits<Scalar>::epsilon() * perm;
    }
    using std::isfinite;
    suspect[f] = !certain || !isfinite(inv) || !isfinite(face[f][0] + face[f][1] + face[f][2]) ? 1 : 0;
  }
}

// The bend angle of hinge h from the face normals: tan(theta/2) by eq. (12), theta = 2 atan2(|n - n~|,
// |n + n~|) (Fig. 3) when `want_theta`; the sign of theta on the flat side (n . n~ >= 0) that of the
// computed determinant, on the folded side the filter's or, when it cannot decide, the exact one.
template <class Scalar>
HINGE_FAST_INLINE BendAngle<Scalar> bend_angle(const Mesh& mesh, const Hinge& h, const std::array<Scalar, 4>& nu,
                                               const std::array<Scalar, 4>& nl, bool want_theta) {
  using std::atan2;
  using std::sqrt;
  const Vec3<Scalar> minus{nu[0] - nl[0], nu[1] - nl[1], nu[2] - nl[2]},
      plus{nu[0] + nl[0], nu[1] + nl[1], nu[2] + nl[2]};
  const Scalar sm = sqrt(vdot(minus, minus)), sp = sqrt(vdot(plus, plus));  // 2 sin(theta/2), 2 cos(theta/2)
  const auto& x0 = mesh.vertices[h.x[0]];
  const auto& x1 = mesh.vertices[h.x[1]];
  const auto& x2 = mesh.vertices[h.x[2]];
  const auto& x3 = mesh.vertices[h.x[3]];
  double p[3], q[3], r[3];
  for (int k = 0; k < 3; ++k) {
    p[k] = x2[k] - x1[k];
    q[k] = x0[k] - x1[k];
    r[k] = x3[k] - x1[k];
  }
  const bool folded_side = nu[0] * nl[0] + nu[1] * nl[1] + nu[2] * nl[2] < 0;
  int sign;
  if (!folded_side) {  // the sign of the computed determinant, which is the filter's answer when it has one
    const double computed = hinge_determinant(p, q, r);
    sign = computed > 0 ? 1 : computed < 0 ? -1 : 0;
  } else {
    double computed;
    sign = orientation_filter(p, q, r, computed);
    if (sign == kUndecided) sign = hinge_orientation_exact(x0, x1, x2, x3);
  }
  BendAngle<Scalar> b;
  if (sign == 0) {  // coplanar: theta is 0 or pi
    b.on_branch_cut = folded_side;
    b.theta = folded_side ? pi_of<Scalar>() : Scalar(0);
    b.tan_half_theta = folded_side ? Scalar(std::numeric_limits<Scalar>::infinity()) : Scalar(0);
    return b;
  }
  b.on_branch_cut = false;
  const Scalar t = sm / sp;  // eq. (12)
  b.tan_half_theta = sign < 0 ? Scalar(-t) : t;
  if (want_theta) {
    const Scalar theta = 2 * atan2(sm, sp);
    b.theta = sign < 0 ? Scalar(-theta) : theta;
  } else {
    b.theta = Scalar(0);  // not used by the tan-based energies
  }
  return b;
}

inline bool needs_theta(Model model) { return model != Model::tan && model != Model::viscoelastic; }

// Scatter helpers: entry (r, c) of the block with `base` and column vertex b is at base + c stride_b +
// (c == 2) + r (pattern.hpp).

// p[0..2] += v. For the vector Column the fourth lane adds +-0 to p[3], which leaves it unchanged: p[3] is
// then the next entry of the same matrix column, which the same thread owns (an off-diagonal block is
// never the last in its column: the diagonal block follows). Not for diagonal blocks.
template <class Scalar>
HINGE_FAST_INLINE void accumulate(Scalar* p, const Column<Scalar>& v) {
  if constexpr (std::is_same_v<Column<Scalar>, Triple<Scalar>>) {
    p[0] += v[0];
    p[1] += v[1];
    p[2] += v[2];
  } else {
    Column<Scalar> x;
    std::memcpy(&x, p, sizeof x);
    x += v;
    std::memcpy(p, &x, sizeof x);
  }
}
// p[0..2] += s g: a vertex's three gradient entries (the next one may be another thread's: not touched).
template <class Scalar>
HINGE_FAST_INLINE void add_scaled(Scalar* p, const Scalar& s, const Vec3<Scalar>& g) {
  if constexpr (std::is_same_v<Column<Scalar>, Triple<Scalar>>) {
    for (int c = 0; c < 3; ++c) p[c] += s * g[c];
  } else {  // the same operations, x and y in one vector
    typedef Scalar Pair __attribute__((vector_size(2 * sizeof(Scalar))));
    Pair x;
    std::memcpy(&x, p, sizeof x);
    x += Pair{s, s} * Pair{g[0], g[1]};
    std::memcpy(p, &x, sizeof x);
    p[2] += s * g[2];
  }
}
// The block with columns B into the off-diagonal block `base` of column vertex b: added, or stored when
// this is the block's first write (Pattern::Face::first: then the values need no zeroing).
template <class Scalar>
HINGE_FAST_INLINE void add_block(Scalar* values, SlotIndex base, SlotIndex stride, const Columns3<Scalar>& B,
                                 bool first) {
  Scalar* col[3] = {values + base, values + base + stride, values + base + 2 * stride + 1};
  if (first) {
    HINGE_FAST_UNROLL
    for (int c = 0; c < 3; ++c) store<Scalar>(col[c], B[c]);
  } else {
    HINGE_FAST_UNROLL
    for (int c = 0; c < 3; ++c) accumulate(col[c], B[c]);
  }
}
// The upper triangle of B into the diagonal block `base` (stride of its vertex), added or stored.
template <class Scalar>
HINGE_FAST_INLINE void add_diagonal(Scalar* values, SlotIndex base, SlotIndex stride, const Columns3<Scalar>& B,
                                    bool first) {
  Scalar* col1 = values + base + stride;
  Scalar* col2 = values + base + 2 * stride + 1;
  if (first) {
    values[base] = B[0][0];
    col1[0] = B[1][0];
    col1[1] = B[1][1];
    col2[0] = B[2][0];
    col2[1] = B[2][1];
    col2[2] = B[2][2];
  } else {
    values[base] += B[0][0];
    col1[0] += B[1][0];
    col1[1] += B[1][1];
    col2[0] += B[2][0];
    col2[1] += B[2][1];
    col2[2] += B[2][2];
  }
}

struct AssemblyFlags {
  bool gradient, hessian;
};
// Column vertices [lo, hi), all of whose faces lie in [face_begin, face_end) (AssemblyPlan).
struct AssemblyRange {
  Index lo, hi;
  std::size_t face_begin, face_end;
};

// The assembly's prefetches: kPrefetchFaces faces ahead, and only for matrices above kPrefetchEntries
// entries (8 MB of doubles: smaller ones live in the cache, where the prefetches only cost). 32 faces is
// the distance the benchmark measured best at 401^2 and 1001^2 (docs/performance-log.md).
constexpr std::size_t kPrefetchFaces = 32;
constexpr std::int64_t kPrefetchEntries = std::int64_t(1) << 20;

// The assembly pass over every face that writes into column vertices [r.lo, r.hi), in increasing order.
template <class Scalar>
HINGE_FAST_INLINE void assembly_pass_body(const Mesh& mesh, const Pattern& pattern, const std::array<Scalar, 4>* face,
                                          const Scalar* psi1, const Scalar* psi2, AssemblyRange r, AssemblyFlags flags,
                                          Scalar* values, Scalar* gradient) {
  const auto& faces = pattern.faces();
  const auto& hinges = pattern.hinges();
  const SlotIndex* stride = pattern.strides().data();
  const SlotIndex* diagonal = pattern.diagonal_bases().data();
  const Index lo = r.lo, hi = r.hi;
  auto mine = [lo, hi](Index v) { return v >= lo && v < hi; };
  // Prefetch (for writing) the columns of each vertex kPrefetchFaces faces before the first face that
  // writes into them: on a matrix larger than the cache those first writes otherwise wait for memory.
  const SlotIndex* outer = pattern.outer().data();
  const Index* order = pattern.first_write_order().data();
  const Index* first_writer = pattern.first_writer().data();
  const std::size_t order_size = pattern.first_write_order().size();
  const bool prefetch = values && pattern.nonzeros() > kPrefetchEntries;
  std::size_t next = 0;
  if (prefetch)
    while (next < order_size && first_writer[order[next]] < static_cast<Index>(r.face_begin)) ++next;
  for (std::size_t f = r.face_begin; f < r.face_end; ++f) {
    if (prefetch)
      for (; next < order_size && first_writer[order[next]] <= static_cast<Index>(f + kPrefetchFaces); ++next) {
        const Index v = order[next];
        if (!mine(v)) continue;
        const char* p = reinterpret_cast<const char*>(values + outer[3 * static_cast<std::size_t>(v)]);
        const char* end = reinterpret_cast<const char*>(values + outer[3 * static_cast<std::size_t>(v) + 3]);
        for (p = reinterpret_cast<const char*>(reinterpret_cast<std::uintptr_t>(p) & ~std::uintptr_t(63)); p < end;
             p += 64)
          __builtin_prefetch(p, 1, 3);
      }
    const Pattern::Face& F = faces[f];
    if (F.highest < lo || F.lowest >= hi) continue;  // writes nothing here (or nothing at all)
    const std::array<Vec3<Scalar>, 3> x{point<Scalar>(mesh, F.v[0]), point<Scalar>(mesh, F.v[1]),
                                        point<Scalar>(mesh, F.v[2])};
    const auto& fd = face[f];
    TriangleGeometry<Scalar> t;
    triangle_geometry(x[0], x[1], x[2], Vec3<Scalar>{fd[0], fd[1], fd[2]}, fd[3], t);  // lines 8-11
    std::array<Scalar, 3> c;
    for (int i = 0; i < 3; ++i) c[i] = F.hinge[i] >= 0 ? psi1[F.hinge[i]] : Scalar(0);  // c_i = sigma_i psi'_i
    // off[i] joins x_i and x_{i+1}; it is kept as stored, transposed when x_{i+1} has the smaller index
    unsigned mirror = 0;
    for (int i = 0; i < 3; ++i) mirror |= unsigned(F.v[(i + 1) % 3] < F.v[i]) << i;
    std::array<Columns3<Scalar>, 3> diag, off;
    if (flags.hessian) triangle_hessian(t, c, F.owns, mirror, diag, off);  // lines 12-13, eq. (7)
    for (int k = 0; k < 3; ++k) {
      if (!((F.owns >> k) & 1u)) continue;  // line 15: the interior edges this face owns
      const Index h = F.hinge[k];
      const Pattern::OwnedHinge& o = hinges[h];
      const int j = next3(k), i = prev3(k);
      const Vec3<Scalar> xs = point<Scalar>(mesh, o.s);
      const auto& ft = face[o.other_face];
      std::array<Vec3<Scalar>, 4> g;                                                      // p, q, r, s
      hinge_gradient(t, k, x[j], x[i], xs, Vec3<Scalar>{ft[0], ft[1], ft[2]}, ft[3], g);  // line 16, eq. (4)
      const Index v[4] = {F.v[k], F.v[j], F.v[i], o.s};
      if (flags.gradient) {
        const Scalar p1 = psi1[h];
        HINGE_FAST_UNROLL4
        for (int a = 0; a < 4; ++a)
          if (mine(v[a])) add_scaled(gradient + 3 * static_cast<std::size_t>(v[a]), p1, g[a]);  // line 17, eq. (2)
      }
      if (flags.hessian) {  // lines 18-19
        const Scalar p2 = psi2[h];
        std::array<Column<Scalar>, 4> pg;
        for (int a = 0; a < 4; ++a) pg[a] = column(g[a]) * p2;
        add_hinge_outer_product(k, pg, g, mirror, diag, off);
        const Index s = o.s;
        Columns3<Scalar> B;
        auto first = [&F, k](int which) { return bool((F.first >> Pattern::hinge_bit(k, which)) & 1u); };
        if (mine(s)) {
          for (int cc = 0; cc < 3; ++cc) B[cc] = pg[3] * g[3][cc];
          add_diagonal(values, diagonal[s], stride[s], B, first(0));
        }
        const SlotIndex slots[3] = {o.slot_ps, o.slot_qs, o.slot_rs};
        HINGE_FAST_UNROLL
        for (int a = 0; a < 3; ++a) {
          const Index u = v[a];
          if (!mine(std::max(u, s))) continue;
          if (u < s) {  // block (u, s): columns pg[a] g_s[c]
            for (int cc = 0; cc < 3; ++cc) B[cc] = pg[a] * g[3][cc];
            add_block(values, slots[a], stride[s], B, first(1 + a));
          } else if (u > s) {  // block (s, u) = its transpose: columns pg[s] g_a[c]
            for (int cc = 0; cc < 3; ++cc) B[cc] = pg[3] * g[a][cc];
            add_block(values, slots[a], stride[u], B, first(1 + a));
          } else {  // u == s (two faces sharing two edges): a diagonal block, B + B^T
            for (int cc = 0; cc < 3; ++cc) B[cc] = pg[a] * g[3][cc] + pg[3] * g[a][cc];
            add_diagonal(values, diagonal[s], stride[s], B, first(1 + a));
          }
        }
      }
    }
    if (flags.hessian) {  // line 14: assemble H^D
      HINGE_FAST_UNROLL
      for (int i = 0; i < 3; ++i) {
        const Index u = F.v[i], w = F.v[(i + 1) % 3];
        if (mine(u)) add_diagonal(values, diagonal[u], stride[u], diag[i], (F.first >> Pattern::diagonal_bit(i)) & 1u);
        const Index top = std::max(u, w);
        if (mine(top))
          add_block(values, F.edge_slot[(i + 2) % 3], stride[top], off[i], (F.first >> Pattern::edge_bit(i)) & 1u);
      }
    }
  }
}

// The two hot passes; for double compiled per instruction set (dispatch.hpp) in assemble_double.cpp.
template <class Scalar>
struct Kernels {
  static void faces(const Mesh& mesh, const Pattern& pattern, std::size_t begin, std::size_t end,
                    std::array<Scalar, 4>* face, char* suspect) {
    face_pass_body<Scalar>(mesh, pattern, begin, end, face, suspect);
  }
  static void assembly(const Mesh& mesh, const Pattern& pattern, const std::array<Scalar, 4>* face, const Scalar* psi1,
                       const Scalar* psi2, AssemblyRange r, AssemblyFlags flags, Scalar* values, Scalar* gradient) {
    assembly_pass_body<Scalar>(mesh, pattern, face, psi1, psi2, r, flags, values, gradient);
  }
};
template <>
void Kernels<double>::faces(const Mesh&, const Pattern&, std::size_t, std::size_t, std::array<double, 4>*, char*);
template <>
void Kernels<double>::assembly(const Mesh&, const Pattern&, const std::array<double, 4>*, const double*, const double*,
                               AssemblyRange, AssemblyFlags, double*, double*);

}  // namespace hinge::fast::detail
