// fast/src/exact.hpp: error-free transformations and a small double-double type, the arithmetic that
// lets the double per-hinge kernel (src/hinge_kernel_lanes.hpp) round each stencil quantity to double
// once; and the floating-point filter for the sign of theta.
//
//   two_sum(a, b)      s + e = a + b exactly (Knuth), any a, b; two_diff(a, b) the same for a - b
//   fast_two_sum(a, b) s + e = a + b exactly when |a| >= |b| or a == 0 (Dekker)
//   two_prod(a, b)     p + e = a b exactly with a fused multiply-add, barring underflow
//
// `DoubleDoubleOf<L>` is the unevaluated sum hi + lo (|lo| <= ulp(hi) / 2 after the operations below),
// with about 106 bits: each operation has a relative error below 2^-100 (a few units of 2^-106; Joldes,
// Muller & Popescu, ACM TOMS 44, 2017, for the algorithms used). Its `hi` is its value rounded to
// double. L is a type of lanes of doubles (lanes.hpp; `Lanes2` below for float's kernel): the same
// operations lane by lane, each lane giving exactly the bits of the scalar code.
//
// two_sum and fast_two_sum serve long double too (the exact sums of hinge_kernel.hpp's wide-range path).
//
// These functions need IEEE double arithmetic with round-to-nearest and no contraction of a * b + c
// into a fused multiply-add behind our back: the project compiles with -ffp-contract=off.
#pragma once

#include <cmath>
#include <type_traits>

#if defined(__GNUC__)
#define HINGE_FAST_INLINE inline __attribute__((always_inline))
// The same for a lambda: written after its parameter list. A lambda is a function of its own, compiled
// for the baseline unless inlined into the function (with its target, dispatch.hpp) that holds it.
#define HINGE_FAST_LAMBDA_INLINE __attribute__((always_inline))
#else
#define HINGE_FAST_INLINE inline
#define HINGE_FAST_LAMBDA_INLINE
#endif
#if defined(__GNUC__) && !defined(__clang__)
#define HINGE_FAST_UNROLL _Pragma("GCC unroll 3")
#define HINGE_FAST_UNROLL4 _Pragma("GCC unroll 4")
#else
#define HINGE_FAST_UNROLL
#define HINGE_FAST_UNROLL4
#endif

namespace hinge::fast {

// Two doubles in one SSE2 register (float's per-hinge kernel computes in them); + - * / act lane by lane.
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
  else if constexpr (requires { L::broadcast(x); }) return L::broadcast(x);  // lanes.hpp
  else return L{x, x};
}

template <class L>
struct DoubleDoubleOf {
  L hi, lo;
};

// Whether W is a double-double of doubles or of lanes of doubles (lanes.hpp), not of long doubles.
template <class W>
inline constexpr bool kDoubleDoubleOfDoubles = false;
template <class L>
inline constexpr bool kDoubleDoubleOfDoubles<DoubleDoubleOf<L>> = !std::is_same_v<L, long double>;

template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> two_sum(L a, L b) {
  const L s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
// s + e = a - b exactly (two_sum(a, -b) without forming -b).
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> two_diff(L a, L b) {
  const L s = a - b, bb = s - a;
  return {s, (a - (s - bb)) - (b + bb)};
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> fast_two_sum(L a, L b) {
  const L s = a + b;
  return {s, b - (s - a)};
}
// a b - p, exactly, for p = a b rounded: a fused multiply-add (lanes.hpp gives the baseline's lanes
// Dekker's product instead, the same bits).
template <class L>
HINGE_FAST_INLINE L product_error(L a, L b, L p) {
  return fused(a, b, -p);
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> two_prod(L a, L b) {
  const L p = a * b;
  return {p, product_error(a, b, p)};
}

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
// a b, relative error ~2^-104: the exact product of the high parts and the first-order terms of the low
// parts (formed apart from it, which keeps the chain of dependent operations short).
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> operator*(const DoubleDoubleOf<L>& a, const DoubleDoubleOf<L>& b) {
  const DoubleDoubleOf<L> p = two_prod(a.hi, b.hi);
  return fast_two_sum(p.hi, p.lo + fused(a.hi, b.lo, a.lo * b.hi));
}
// Newton's step for 1 / sqrt(a) from an estimate y (relative error a few units of 2^-53), as the factor
// it applies: 1 / sqrt(a) = y (1 + e/2) with relative error of order e^2 ~ 2^-104, e = 1 - a y^2. Returns
// e/2 (y^2 exact, two_prod; a y^2 - 1 by a fused multiply-add, exact but for its last rounding). Kept as
// a factor, the step folds into the products that use 1 / sqrt(a) instead of adding its latency.
template <class L>
HINGE_FAST_INLINE L rsqrt_correction(const DoubleDoubleOf<L>& a, const L& y) {
  const DoubleDoubleOf<L> y2 = two_prod(y, y);
  return -((fused(a.hi, y2.hi, -splat<L>(1)) + a.hi * y2.lo) + a.lo * y2.hi) * 0.5;
}
// c y (1 + h), for h small (rsqrt_correction): c.hi y exactly, the rest to first order.
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> times_corrected(const DoubleDoubleOf<L>& c, const L& y, const L& h) {
  const DoubleDoubleOf<L> p = two_prod(c.hi, y);
  return fast_two_sum(p.hi, (p.lo + c.lo * y) + p.hi * h);
}

// The sign of det[e0, x0 - x1, x1 - x3] (the sign of theta, proofs/sign-convention.md) from the
// rounded differences p = fl(x2 - x1), q = fl(x0 - x1), r = fl(x3 - x1), each possibly times one exact
// power of two: -1, 0 or +1 when certified, kUndecided otherwise (then hinge_orientation_exact decides).
// This is the filter of core/src/predicates.cpp (bound fl(9 u P'), guard [2^-300, 2^300]), with the
// same proof; `computed` receives the (uncertified) hinge determinant.
constexpr int kUndecided = 2;
// The hinge determinant -det[p, q, r] = -sum_k p_k (q_i r_j - q_j r_i), (i, j) = (k + 1, k + 2) mod 3, in
// this order: the filter's `computed`, bit for bit.
HINGE_FAST_INLINE double hinge_determinant(const double p[3], const double q[3], const double r[3]) {
  double det = 0.0;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    det += p[k] * (q[i] * r[j] - q[j] * r[i]);
  }
  return -det;
}
// Without branches: the sign of theta is data (random in a benchmark, alternating on a mesh), and a
// mispredicted branch in the middle of a kernel discards the work that followed it.
// When it decides a nonzero sign, that sign is the sign of `computed` (|computed| exceeds a bound that is
// not negative), and when it decides 0 (perm == 0 inside the guard: every term exactly 0), `computed` is 0.
// So on the flat side, where the mesh path takes the sign of `computed` when the filter cannot decide
// (assemble.hpp), that sign is the answer either way (tests/fast/exact_test.cpp).
HINGE_FAST_INLINE int orientation_filter(const double p[3], const double q[3], const double r[3], double& computed) {
  constexpr double lo = 0x1p-300, hi = 0x1p300, u = 0x1p-53;
  bool guarded = true;
  double perm = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double a = std::fabs(p[k]), b = std::fabs(q[k]), c = std::fabs(r[k]);
    guarded &= ((a == 0.0) | ((a >= lo) & (a <= hi))) & ((b == 0.0) | ((b >= lo) & (b <= hi))) &
               ((c == 0.0) | ((c >= lo) & (c <= hi)));
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    perm += a * (std::fabs(q[i] * r[j]) + std::fabs(q[j] * r[i]));
  }
  computed = hinge_determinant(p, q, r);
  const double det = -computed;
  const double bound = 9.0 * u * perm;
  const int negative = det > bound, positive = -det > bound;
  // perm == 0: every term is zero, so the determinant is exactly 0.
  const int decided = guarded & (negative | positive | (perm == 0.0));
  return decided ? positive - negative : kUndecided;
}

}  // namespace hinge::fast
