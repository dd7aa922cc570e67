// hinge/reference/stencil.hpp: the hinge stencil of the paper's Fig. 1 (which the seed text lacks),
// settled by derivation (proofs/gradient.md, proofs/hessian.md) and documented in docs/stencil.md.
//
//                 x0                 upper triangle T = (x0, x1, x2), counter-clockwise about n
//          e1   /  \   e2            e_i = x_{i+2} - x_{i+1}: e0 = x2 - x1, e1 = x0 - x2, e2 = x1 - x0
//              / T  \                n = N / |N|,  N = (x1 - x0) x (x2 - x0)
//            x1 ---> x2   e0         alpha_i: interior angle at x_i;  h_i: altitude from x_i onto e_i
//              \ T~ /                m_i: unit in-plane normal of e_i pointing out of the triangle
//          e~2  \  /  e~1
//                x3                  lower triangle in the paper's labels (x~0, x~1, x~2) = (x3, x1, x2),
//                                    traversed clockwise about n~ = Nt / |Nt|, Nt = (x2 - x3) x (x1 - x3);
//    e~_i = x~_{i+2} - x~_{i+1}: e~0 = x2 - x1 = e0, e~1 = x3 - x2, e~2 = x1 - x3; alpha~_i, h~_i, m~_i
//    as above, m~_i again pointing OUT of T~ (so m~_i = n~ x e~_i / |e~_i|, the mirror of m_i = ê_i x n;
//    Algorithm 2's m_i = ê_i x n applied to the clockwise tilde labels would point inward: erratum E5).
//
// Variables: x0, x1, x2, x3 (12). Edge labels follow the opposite vertex (the paper's section 2).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <array>

#include "hinge/core/scalar.hpp"

namespace hinge::reference {

template <class Scalar>
using Vec3 = Eigen::Matrix<Scalar, 3, 1>;
template <class Scalar>
using Mat3 = Eigen::Matrix<Scalar, 3, 3>;

// The five edge vectors of a hinge, each one subtraction of input coordinates (so that rounding errors
// do not grow when every point is translated far from the origin).
template <class Scalar>
struct HingeEdges {
  Vec3<Scalar> e0;   // x2 - x1, the hinge edge
  Vec3<Scalar> e1;   // x0 - x2
  Vec3<Scalar> e2;   // x1 - x0
  Vec3<Scalar> et1;  // e~1 = x3 - x2
  Vec3<Scalar> et2;  // e~2 = x1 - x3
};

// Edges from the 12 input doubles (x0.x, x0.y, ..., x3.z). Every difference is taken in a type at least
// as wide as double (for float: in double, then rounded once), exactly where Scalar is wide enough.
template <HingeScalar Scalar>
HingeEdges<Scalar> hinge_edges(const std::array<double, 12>& x) {
  auto diff = [&x](int a, int b) {
    Vec3<Scalar> d;
    for (int c = 0; c < 3; ++c) {
      if constexpr (std::same_as<Scalar, float>) d[c] = static_cast<float>(x[3 * a + c] - x[3 * b + c]);
      else d[c] = from_double<Scalar>(x[3 * a + c]) - from_double<Scalar>(x[3 * b + c]);
    }
    return d;
  };
  return {diff(2, 1), diff(0, 2), diff(1, 0), diff(3, 2), diff(1, 3)};
}

// The same from positions already in Scalar.
template <HingeScalar Scalar>
HingeEdges<Scalar> hinge_edges(const std::array<Vec3<Scalar>, 4>& x) {
  return {x[2] - x[1], x[0] - x[2], x[1] - x[0], x[3] - x[2], x[1] - x[3]};
}

// a b exactly, as p + e with p = fl(a b) (Dekker's product with Veltkamp's split into two halves of 32
// bits; Dekker, Numer. Math. 18, 1971). For long double, whose fused multiply-add is emulated in glibc
// (fmal saves and restores the floating-point environment: about 40 times slower than these 17
// operations). Exact barring overflow and underflow of the products.
inline void exact_product(long double a, long double b, long double& p, long double& e) {
  constexpr long double split = 4294967297.0L;  // 2^32 + 1: long double has a 64-bit significand
  const long double ca = split * a, a_hi = ca - (ca - a), a_lo = a - a_hi;
  const long double cb = split * b, b_hi = cb - (cb - b), b_lo = b - b_hi;
  p = a * b;
  e = ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
}

// a b - c d to a few units of roundoff of the result, also where the two products nearly cancel: in
// float and double by Kahan's algorithm with the hardware fused multiply-add (at most 2 units; Jeannerod,
// Louvet & Muller, Math. Comp. 82, 2013); in long double from the two exact products, (p1 - p2) + (e1 -
// e2) (the algorithm of Cornea, Harrison & Tang, 2002: a few units; p1 - p2 is exact where it cancels,
// by Sterbenz's lemma); plainly in the multiprecision types. The components of a cross product are
// such differences and cancel in needle and obtuse triangles; this keeps N to a few units where the
// stencil is computed in long double (the double reference's stencil) or double (the float
// reference's). Plain products would give a needle's N a relative error ~kappa_shape 2^-64, which the
// cancellation of N0 + N~0 on near-flat hinges amplifies to no correct digit (docs/testing.md, Findings 1).
template <class Scalar>
Scalar difference_of_products(const Scalar& a, const Scalar& b, const Scalar& c, const Scalar& d) {
  if constexpr (std::same_as<Scalar, float> || std::same_as<Scalar, double>) {
    using std::fma;
    const Scalar cd = c * d;
    const Scalar error = fma(-c, d, cd);  // cd - c d exactly
    return fma(a, b, -cd) + error;
  } else if constexpr (std::same_as<Scalar, long double>) {
    long double p1, e1, p2, e2;
    exact_product(a, b, p1, e1);
    exact_product(c, d, p2, e2);
    return (p1 - p2) + (e1 - e2);
  } else {
    return a * b - c * d;
  }
}

// u x v, each component by difference_of_products.
template <class Scalar>
Vec3<Scalar> cross(const Vec3<Scalar>& u, const Vec3<Scalar>& v) {
  return {difference_of_products(u[1], v[2], u[2], v[1]), difference_of_products(u[2], v[0], u[0], v[2]),
          difference_of_products(u[0], v[1], u[1], v[0])};
}

// One triangle of the stencil in the paper's labels (y0, y1, y2), edges e_i = y_{i+2} - y_{i+1}.
template <class Scalar>
struct Triangle {
  std::array<Vec3<Scalar>, 3> e;    // edge vectors
  std::array<Scalar, 3> l;          // |e_i|
  Scalar double_area;               // 2A = |N|
  Vec3<Scalar> n;                   // unit normal: n, or n~ for the lower triangle
  std::array<Scalar, 3> h;          // altitudes h_i = 2A / l_i (Algorithm 2, line 10)
  std::array<Scalar, 3> cos_alpha;  // cos alpha_i = -ê_{i+1} . ê_{i+2}: the angle at y_i (erratum E3)
  std::array<Vec3<Scalar>, 3> m;    // outward unit edge normals
};

// `normal` is the unnormalized N (or Nt); `counter_clockwise` says whether the labels run
// counter-clockwise about it (true for T, false for T~), which fixes the outward side of each edge.
template <class Scalar>
Triangle<Scalar> make_triangle(const Vec3<Scalar>& e0, const Vec3<Scalar>& e1, const Vec3<Scalar>& e2,
                               const Vec3<Scalar>& normal, bool counter_clockwise) {
  Triangle<Scalar> t;
  t.e = {e0, e1, e2};
  t.double_area = normal.norm();
  t.n = normal / t.double_area;
  std::array<Vec3<Scalar>, 3> unit;
  for (int i = 0; i < 3; ++i) {
    t.l[i] = t.e[i].norm();
    unit[i] = t.e[i] / t.l[i];
    t.h[i] = t.double_area / t.l[i];
    t.m[i] = counter_clockwise ? cross(unit[i], t.n) : cross(t.n, unit[i]);
  }
  for (int i = 0; i < 3; ++i) t.cos_alpha[i] = -unit[(i + 1) % 3].dot(unit[(i + 2) % 3]);
  return t;
}

// Fig. 1: both triangles of a hinge, and the unnormalized normals of docs/contract.md.
template <class Scalar>
struct Stencil {
  Vec3<Scalar> N;          // (x1 - x0) x (x2 - x0)
  Vec3<Scalar> Nt;         // (x2 - x3) x (x1 - x3)
  Triangle<Scalar> upper;  // T
  Triangle<Scalar> lower;  // T~, in the paper's labels (x3, x1, x2)
};

template <class Scalar>
Stencil<Scalar> make_stencil(const HingeEdges<Scalar>& x) {
  Stencil<Scalar> s;
  // (x1 - x0) x (x2 - x0) = (x1 - x0) x (x2 - x1) and (x2 - x3) x (x1 - x3) = (x2 - x1) x (x1 - x3): formed
  // with the hinge edge, N and Nt stay perpendicular to it to working precision even when it is much
  // shorter than the other edges (the two long edges' product would lose log2(L / |e0|) bits: 2.5e12 units
  // of 2^-53 in theta at |e0| = 2^-60 L, hinge conform's short-hinge-edges category).
  s.N = cross<Scalar>(x.e2, x.e0);    // (x1 - x0) x (x2 - x0)
  s.Nt = cross<Scalar>(x.e0, x.et2);  // (x2 - x3) x (x1 - x3)
  s.upper = make_triangle<Scalar>(x.e0, x.e1, x.e2, s.N, true);
  s.lower = make_triangle<Scalar>(x.e0, x.et1, x.et2, s.Nt, false);
  return s;
}

// The stencil of Scalar rounded to Target, quantity by quantity.
template <class Target, class Scalar>
Triangle<Target> round_to(const Triangle<Scalar>& t) {
  Triangle<Target> r;
  auto round = [](const Scalar& v) { return static_cast<Target>(v); };
  for (int i = 0; i < 3; ++i) {
    r.e[i] = t.e[i].unaryExpr(round);
    r.l[i] = round(t.l[i]);
    r.h[i] = round(t.h[i]);
    r.cos_alpha[i] = round(t.cos_alpha[i]);
    r.m[i] = t.m[i].unaryExpr(round);
  }
  r.double_area = round(t.double_area);
  r.n = t.n.unaryExpr(round);
  return r;
}
template <class Target, class Scalar>
Stencil<Target> round_to(const Stencil<Scalar>& s) {
  auto round = [](const Scalar& v) { return static_cast<Target>(v); };
  return {s.N.unaryExpr(round), s.Nt.unaryExpr(round), round_to<Target>(s.upper), round_to<Target>(s.lower)};
}

}  // namespace hinge::reference
