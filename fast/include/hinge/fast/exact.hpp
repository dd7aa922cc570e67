// hinge/fast/exact.hpp: error-free transformations and a small double-double type, the arithmetic that
// lets the per-hinge kernel (hinge_kernel.hpp) round each stencil quantity to double once.
//
//   two_sum(a, b)      s + e = a + b exactly (Knuth), any a, b
//   fast_two_sum(a, b) s + e = a + b exactly when |a| >= |b| or a == 0 (Dekker)
//   two_prod(a, b)     p + e = a b exactly with a fused multiply-add, barring underflow
//
// `DoubleDoubleOf<L>` is the unevaluated sum hi + lo (|lo| <= ulp(hi) / 2 after the operations below),
// with about 106 bits: each operation has a relative error below 2^-100 (a few units of 2^-106; Joldes,
// Muller & Popescu, ACM TOMS 44, 2017, for the algorithms used). Its `hi` is its value rounded to
// double. L is double, or `Lanes2` (two doubles in one register, GCC vector extension): the same
// operations lane by lane, so that the kernel treats the two triangles of a hinge at once, each lane
// giving exactly the bits of the scalar code.
//
// two_sum and fast_two_sum serve long double too (the exact sums of hinge_kernel.hpp's wide-range path).
//
// These functions need IEEE double arithmetic with round-to-nearest and no contraction of a * b + c
// into a fused multiply-add behind our back: fast/CMakeLists.txt compiles with -ffp-contract=off.
#pragma once

#include <cmath>
#include <type_traits>

#if defined(__GNUC__)
#define HINGE_FAST_INLINE inline __attribute__((always_inline))
#else
#define HINGE_FAST_INLINE inline
#endif
#if defined(__GNUC__) && !defined(__clang__)
#define HINGE_FAST_UNROLL _Pragma("GCC unroll 3")
#else
#define HINGE_FAST_UNROLL
#endif

namespace hinge::fast {

// Two doubles in one SSE2 register; + - * / act lane by lane.
typedef double Lanes2 __attribute__((vector_size(16)));

// Lane-wise fused multiply-add and square root (where the processor has FMA the compiler makes one vector
// instruction of the pair).
HINGE_FAST_INLINE double fused(double a, double b, double c) { return std::fma(a, b, c); }
HINGE_FAST_INLINE Lanes2 fused(Lanes2 a, Lanes2 b, Lanes2 c) {
  return Lanes2{std::fma(a[0], b[0], c[0]), std::fma(a[1], b[1], c[1])};
}
HINGE_FAST_INLINE double root(double a) { return std::sqrt(a); }
HINGE_FAST_INLINE Lanes2 root(Lanes2 a) { return Lanes2{std::sqrt(a[0]), std::sqrt(a[1])}; }

template <class L>
HINGE_FAST_INLINE L splat(double x) {
  if constexpr (std::is_same_v<L, double>) return x;
  else return L{x, x};
}

template <class L>
struct DoubleDoubleOf {
  L hi, lo;
};
using DoubleDouble = DoubleDoubleOf<double>;
using DoubleDouble2 = DoubleDoubleOf<Lanes2>;

template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> two_sum(L a, L b) {
  const L s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> fast_two_sum(L a, L b) {
  const L s = a + b;
  return {s, b - (s - a)};
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> two_prod(L a, L b) {
  const L p = a * b;
  return {p, fused(a, b, -p)};
}
// a - b exactly.
HINGE_FAST_INLINE DoubleDouble two_diff(double a, double b) { return two_sum(a, -b); }

template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> operator-(const DoubleDoubleOf<L>& a) {
  return {-a.hi, -a.lo};
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> operator+(const DoubleDoubleOf<L>& a, const DoubleDoubleOf<L>& b) {
  const DoubleDoubleOf<L> s = two_sum(a.hi, b.hi);
  return fast_two_sum(s.hi, s.lo + (a.lo + b.lo));
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> operator-(const DoubleDoubleOf<L>& a, const DoubleDoubleOf<L>& b) {
  return a + (-b);
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> operator*(const DoubleDoubleOf<L>& a, const DoubleDoubleOf<L>& b) {
  const DoubleDoubleOf<L> p = two_prod(a.hi, b.hi);
  return fast_two_sum(p.hi, fused(a.hi, b.lo, fused(a.lo, b.hi, p.lo)));
}
// One Newton step on the double quotient: relative error ~2^-104.
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> operator/(const DoubleDoubleOf<L>& a, const DoubleDoubleOf<L>& b) {
  const L q = a.hi / b.hi;
  const DoubleDoubleOf<L> p = two_prod(q, b.hi);  // q b, to first order
  const L r = ((a.hi - p.hi) - p.lo + a.lo) - q * b.lo;
  return fast_two_sum(q, r / b.hi);
}
// 1 / sqrt(a): y' = y + y (1 - a y^2) / 2 from the double result y.
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> rsqrt(const DoubleDoubleOf<L>& a) {
  const L one = splat<L>(1);
  const L y = one / root(a.hi);
  const DoubleDoubleOf<L> ay2 = a * two_prod(y, y);
  const L e = (one - ay2.hi) - ay2.lo;
  return fast_two_sum(y, y * e * 0.5);
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> half(const DoubleDoubleOf<L>& a) {
  return {a.hi * 0.5, a.lo * 0.5};
}

// The sign of det[e0, x0 - x1, x1 - x3] (the sign of theta, proofs/sign-convention.md) from the
// rounded differences p = fl(x2 - x1), q = fl(x0 - x1), r = fl(x3 - x1), each possibly times one exact
// power of two: -1, 0 or +1 when certified, kUndecided otherwise (then hinge_orientation_exact decides).
// This is the filter of reference/src/predicates.cpp (bound fl(9 u P'), guard [2^-300, 2^300]), with the
// same proof; `computed` receives the (uncertified) hinge determinant.
constexpr int kUndecided = 2;
HINGE_FAST_INLINE int orientation_filter(const double p[3], const double q[3], const double r[3], double& computed) {
  constexpr double lo = 0x1p-300, hi = 0x1p300, u = 0x1p-53;
  bool guarded = true;
  double det = 0.0, perm = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double a = std::fabs(p[k]), b = std::fabs(q[k]), c = std::fabs(r[k]);
    guarded = guarded && (a == 0.0 || (a >= lo && a <= hi)) && (b == 0.0 || (b >= lo && b <= hi)) &&
              (c == 0.0 || (c >= lo && c <= hi));
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double m1 = q[i] * r[j], m2 = q[j] * r[i];
    det += p[k] * (m1 - m2);
    perm += a * (std::fabs(m1) + std::fabs(m2));
  }
  computed = -det;  // the hinge determinant is -det[p, q, r]
  if (!guarded) return kUndecided;
  if (perm == 0.0) return 0;
  const double bound = 9.0 * u * perm;
  if (det > bound) return -1;
  if (-det > bound) return 1;
  return kUndecided;
}

}  // namespace hinge::fast
