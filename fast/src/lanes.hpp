// fast/src/lanes.hpp: eight doubles as two halves of four lanes, the unit of the double per-hinge kernel
// (src/hinge_kernel_lanes.hpp), which keeps the upper triangle of a hinge in one half and the lower
// triangle in the other, one edge (or one dot product) per lane.
//
//   Zmm8   one 512-bit register (AVX-512: x86-64-v4)
//   Ymm8   two 256-bit registers (AVX2 and FMA: x86-64-v3)
//   Sse8   two 256-bit vectors of the baseline x86-64 (the compiler makes pairs of SSE registers of them;
//          its fused multiply-add emulated exactly: fused_without_fma)
//
// All offer the same operations, lane by lane IEEE arithmetic (+ - * /, fused multiply-add, square root)
// and shuffles whose pattern is the same in both halves, so that a kernel written once computes the same
// bits with any of them. Every function is always_inline, so that it is compiled for the instruction set
// of the function it is inlined into (dispatch.hpp); Zmm8 and Ymm8 live only in functions compiled for
// AVX-512 and for AVX2 respectively.
#pragma once

#include <emmintrin.h>

#include <cmath>
#include <cstring>
#include <type_traits>

#include "exact.hpp"

#if defined(__GNUC__) && !defined(__clang__)
// The vectors never cross a non-inlined call: the ABI note about passing them without AVX is moot.
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace hinge::fast {

typedef double Double8 __attribute__((vector_size(64)));
typedef double Double4 __attribute__((vector_size(32)));
typedef long long Index8 __attribute__((vector_size(64)));
typedef long long Index4 __attribute__((vector_size(32)));
typedef double Double2 __attribute__((vector_size(16)));  // one SSE2 register, as __m128d
typedef long long Index2 __attribute__((vector_size(16)));

struct Zmm8 {
  Double8 v;
  static HINGE_FAST_INLINE Zmm8 make(double a0, double a1, double a2, double a3, double b0, double b1, double b2,
                                     double b3) {
    return {Double8{a0, a1, a2, a3, b0, b1, b2, b3}};
  }
  static HINGE_FAST_INLINE Zmm8 broadcast(double x) { return {Double8{x, x, x, x, x, x, x, x}}; }
  HINGE_FAST_INLINE double lane(int i) const { return v[i]; }
  // The low half (lanes 0 .. 3) and the high half (lanes 4 .. 7).
  HINGE_FAST_INLINE Double4 lo4() const {
    Double4 r;
    std::memcpy(&r, &v, sizeof r);
    return r;
  }
  HINGE_FAST_INLINE Double4 hi4() const {
    Double4 r;
    std::memcpy(&r, reinterpret_cast<const char*>(&v) + sizeof r, sizeof r);
    return r;
  }
  friend HINGE_FAST_INLINE Zmm8 operator+(Zmm8 a, Zmm8 b) { return {a.v + b.v}; }
  friend HINGE_FAST_INLINE Zmm8 operator-(Zmm8 a, Zmm8 b) { return {a.v - b.v}; }
  friend HINGE_FAST_INLINE Zmm8 operator*(Zmm8 a, Zmm8 b) { return {a.v * b.v}; }
  friend HINGE_FAST_INLINE Zmm8 operator/(Zmm8 a, Zmm8 b) { return {a.v / b.v}; }
  friend HINGE_FAST_INLINE Zmm8 operator*(Zmm8 a, double b) { return {a.v * b}; }
  friend HINGE_FAST_INLINE Zmm8 operator-(Zmm8 a) { return {-a.v}; }
};

// kAvx2: the fused multiply-add and the square root are AVX instructions (else lane by lane).
template <bool kAvx2>
struct Halves8 {
  Double4 h[2];
  static HINGE_FAST_INLINE Halves8 make(double a0, double a1, double a2, double a3, double b0, double b1, double b2,
                                        double b3) {
    return {{Double4{a0, a1, a2, a3}, Double4{b0, b1, b2, b3}}};
  }
  static HINGE_FAST_INLINE Halves8 broadcast(double x) { return {{Double4{x, x, x, x}, Double4{x, x, x, x}}}; }
  HINGE_FAST_INLINE double lane(int i) const { return h[i >> 2][i & 3]; }
  HINGE_FAST_INLINE Double4 lo4() const { return h[0]; }
  HINGE_FAST_INLINE Double4 hi4() const { return h[1]; }
  friend HINGE_FAST_INLINE Halves8 operator+(Halves8 a, Halves8 b) { return {{a.h[0] + b.h[0], a.h[1] + b.h[1]}}; }
  friend HINGE_FAST_INLINE Halves8 operator-(Halves8 a, Halves8 b) { return {{a.h[0] - b.h[0], a.h[1] - b.h[1]}}; }
  friend HINGE_FAST_INLINE Halves8 operator*(Halves8 a, Halves8 b) { return {{a.h[0] * b.h[0], a.h[1] * b.h[1]}}; }
  friend HINGE_FAST_INLINE Halves8 operator/(Halves8 a, Halves8 b) { return {{a.h[0] / b.h[0], a.h[1] / b.h[1]}}; }
  friend HINGE_FAST_INLINE Halves8 operator*(Halves8 a, double b) { return {{a.h[0] * b, a.h[1] * b}}; }
  friend HINGE_FAST_INLINE Halves8 operator-(Halves8 a) { return {{-a.h[0], -a.h[1]}}; }
};
using Ymm8 = Halves8<true>;
using Sse8 = Halves8<false>;

// e with p + e = a b exactly, p = a b rounded (Dekker's product with Veltkamp's split), where the split
// does not overflow (|a|, |b| < 2^995) and the error does not underflow: what a fused multiply-add gives
// for a b - p, at a third of fused_without_fma's cost.
HINGE_FAST_INLINE Double2 product_error_without_fma(Double2 a, Double2 b, Double2 p) {
  const Double2 veltkamp = Double2{} + 134217729.0;  // 2^27 + 1
  const Double2 ta = a * veltkamp, ah = ta - (ta - a), al = a - ah;
  const Double2 tb = b * veltkamp, bh = tb - (tb - b), bl = b - bh;
  return (((ah * bh - p) + ah * bl) + al * bh) + al * bl;
}
// a b + c rounded once, lane by lane, with neither a fused multiply-add instruction nor a library call (the
// baseline x86-64 has no FMA, and libm's fma is a call that spills every vector register): the exact
// product p + e = a b above; then Boldo and Melquiond's emulation (IEEE Trans. Computers
// 57(4), 2008, "Emulation of FMA and correctly rounded sums: proved algorithms using rounding to odd"):
// th + tl = c + p exactly, v = tl + e rounded to odd (rounded to nearest, then moved one unit towards the
// exact sum where that is inexact and the last bit even), the result th + v rounded to nearest. The same
// bits as a fused multiply-add under the product's conditions (the kernels' rescaled stencils stay far
// inside them). A zero product takes the
// plain sum c + p, which carries the fused multiply-add's sign of zero.
HINGE_FAST_INLINE Double2 fused_without_fma(Double2 a, Double2 b, Double2 c) {
  const Double2 p = a * b;
  const Double2 e = product_error_without_fma(a, b, p);  // p + e = a b exactly
  const Double2 th = c + p, zc = th - c;
  const Double2 tl = (c - (th - zc)) + (p - zc);  // th + tl = c + p exactly (Knuth)
  const Double2 s = tl + e, ze = s - tl;
  const Double2 r = (tl - (s - ze)) + (e - ze);  // s + r = tl + e exactly
  // The masks by SSE2's double compares (as vector comparisons GCC would compare lane by lane in scalars).
  const Double2 zero{};
  Index2 bits = reinterpret_cast<Index2>(s);
  const Index2 to_odd = (1 - (bits & 1)) & reinterpret_cast<Index2>(_mm_cmpneq_pd(r, zero));  // inexact, even: 1
  const Index2 away = reinterpret_cast<Index2>(_mm_xor_pd(_mm_cmplt_pd(s, zero), _mm_cmplt_pd(r, zero)));
  bits += (to_odd ^ away) - away;  // one unit up, or down where r points towards zero: s + r rounded to odd
  const Double2 zero_product = _mm_cmpeq_pd(p, zero);
  return _mm_or_pd(_mm_and_pd(zero_product, c + p), _mm_andnot_pd(zero_product, th + reinterpret_cast<Double2>(bits)));
}
// The same on four lanes, as two SSE2 registers.
template <class Op>
HINGE_FAST_INLINE Double4 on_halves(Double4 a, Double4 b, Double4 c, Op op) {
  Double2 a2[2], b2[2], c2[2];
  std::memcpy(a2, &a, sizeof a), std::memcpy(b2, &b, sizeof b), std::memcpy(c2, &c, sizeof c);
  const Double2 r2[2] = {op(a2[0], b2[0], c2[0]), op(a2[1], b2[1], c2[1])};
  Double4 r;
  std::memcpy(&r, r2, sizeof r);
  return r;
}
HINGE_FAST_INLINE Double4 fused_without_fma(Double4 a, Double4 b, Double4 c) {
  return on_halves(a, b, c,
                   [](Double2 x, Double2 y, Double2 z) HINGE_FAST_LAMBDA_INLINE { return fused_without_fma(x, y, z); });
}
HINGE_FAST_INLINE Double4 product_error_without_fma(Double4 a, Double4 b, Double4 p) {
  return on_halves(a, b, p, [](Double2 x, Double2 y, Double2 z) HINGE_FAST_LAMBDA_INLINE {
    return product_error_without_fma(x, y, z);
  });
}

// Lane by lane a b + c (one rounding) and sqrt(a): for Zmm8 and Ymm8 the AVX-512 and AVX instructions, as
// inline assembly (GCC offers no vector fused multiply-add that an inlined helper may use whatever its
// caller's target: the intrinsics refuse to inline into functions not compiled for them, and a
// lane-by-lane loop is vectorized or not depending on its surroundings); for Sse8 fused_without_fma.
HINGE_FAST_INLINE Zmm8 fused(Zmm8 a, Zmm8 b, Zmm8 c) {
  asm("vfmadd231pd %2, %1, %0" : "+v"(c.v) : "v"(a.v), "v"(b.v));
  return c;
}
HINGE_FAST_INLINE Zmm8 root(Zmm8 a) {
  Zmm8 r;
  asm("vsqrtpd %1, %0" : "=v"(r.v) : "v"(a.v));
  return r;
}
template <bool kAvx2>
HINGE_FAST_INLINE Halves8<kAvx2> fused(Halves8<kAvx2> a, Halves8<kAvx2> b, Halves8<kAvx2> c) {
  for (int k = 0; k < 2; ++k) {
    if constexpr (kAvx2) asm("vfmadd231pd %2, %1, %0" : "+x"(c.h[k]) : "x"(a.h[k]), "x"(b.h[k]));
    else c.h[k] = fused_without_fma(a.h[k], b.h[k], c.h[k]);
  }
  return c;
}
// a b - p exactly for p = a b rounded (exact.hpp's product_error): on the baseline by Dekker's product.
template <bool kAvx2>
HINGE_FAST_INLINE Halves8<kAvx2> product_error(Halves8<kAvx2> a, Halves8<kAvx2> b, Halves8<kAvx2> p) {
  if constexpr (kAvx2) return fused(a, b, -p);
  else return {{product_error_without_fma(a.h[0], b.h[0], p.h[0]), product_error_without_fma(a.h[1], b.h[1], p.h[1])}};
}
template <bool kAvx2>
HINGE_FAST_INLINE Halves8<kAvx2> root(Halves8<kAvx2> a) {
  Halves8<kAvx2> r;
  for (int k = 0; k < 2; ++k) {
    if constexpr (kAvx2) asm("vsqrtpd %1, %0" : "=x"(r.h[k]) : "x"(a.h[k]));
    else
      for (int i = 0; i < 4; ++i) r.h[k][i] = __builtin_sqrt(a.h[k][i]);
  }
  return r;
}

// Lane j of each half takes lane p_j of the same half.
template <int p0, int p1, int p2, int p3>
HINGE_FAST_INLINE Zmm8 permute(Zmm8 a) {
  return {__builtin_shuffle(a.v, Index8{p0, p1, p2, p3, p0 + 4, p1 + 4, p2 + 4, p3 + 4})};
}
template <int p0, int p1, int p2, int p3, bool kAvx2>
HINGE_FAST_INLINE Halves8<kAvx2> permute(Halves8<kAvx2> a) {
  return {{__builtin_shuffle(a.h[0], Index4{p0, p1, p2, p3}), __builtin_shuffle(a.h[1], Index4{p0, p1, p2, p3})}};
}
// Lane j of each half from b where b_j is 1, else from a.
template <int b0, int b1, int b2, int b3>
HINGE_FAST_INLINE Zmm8 blend(Zmm8 a, Zmm8 b) {
  return {__builtin_shuffle(
      a.v, b.v,
      Index8{b0 ? 8 : 0, b1 ? 9 : 1, b2 ? 10 : 2, b3 ? 11 : 3, b0 ? 12 : 4, b1 ? 13 : 5, b2 ? 14 : 6, b3 ? 15 : 7})};
}
template <int b0, int b1, int b2, int b3, bool kAvx2>
HINGE_FAST_INLINE Halves8<kAvx2> blend(Halves8<kAvx2> a, Halves8<kAvx2> b) {
  constexpr Index4 m{b0 ? 4 : 0, b1 ? 5 : 1, b2 ? 6 : 2, b3 ? 7 : 3};
  return {{__builtin_shuffle(a.h[0], b.h[0], m), __builtin_shuffle(a.h[1], b.h[1], m)}};
}
// Lane j of each half takes lane i_j (0 .. 3) of a's same half, or lane i_j - 4 of b's (i_j in 4 .. 7).
template <int i0, int i1, int i2, int i3>
HINGE_FAST_INLINE Zmm8 shuffle(Zmm8 a, Zmm8 b) {
  constexpr auto at = [](int i, int h) { return i < 4 ? 4 * h + i : 8 + 4 * h + (i - 4); };
  return {__builtin_shuffle(
      a.v, b.v, Index8{at(i0, 0), at(i1, 0), at(i2, 0), at(i3, 0), at(i0, 1), at(i1, 1), at(i2, 1), at(i3, 1)})};
}
template <int i0, int i1, int i2, int i3, bool kAvx2>
HINGE_FAST_INLINE Halves8<kAvx2> shuffle(Halves8<kAvx2> a, Halves8<kAvx2> b) {
  constexpr Index4 m{i0, i1, i2, i3};
  return {{__builtin_shuffle(a.h[0], b.h[0], m), __builtin_shuffle(a.h[1], b.h[1], m)}};
}
// The two halves exchanged.
HINGE_FAST_INLINE Zmm8 swap_halves(Zmm8 a) { return {__builtin_shuffle(a.v, Index8{4, 5, 6, 7, 0, 1, 2, 3})}; }
template <bool kAvx2>
HINGE_FAST_INLINE Halves8<kAvx2> swap_halves(Halves8<kAvx2> a) {
  return {{a.h[1], a.h[0]}};
}
// Every lane of a half takes lane j of that half.
template <int j, class L>
HINGE_FAST_INLINE L spread(L a) {
  return permute<j, j, j, j>(a);
}

// Lane l takes x[i_l] of twelve doubles x (for AVX-512 two loads and one shuffle).
template <class L, int i0, int i1, int i2, int i3, int i4, int i5, int i6, int i7>
HINGE_FAST_INLINE L pick12(const double* x) {
  if constexpr (std::is_same_v<L, Zmm8>) {
    Double8 a, b;  // x[0 .. 7], x[4 .. 11]
    std::memcpy(&a, x, sizeof a);
    std::memcpy(&b, x + 4, sizeof b);
    constexpr auto at = [](int i) { return i < 8 ? i : 8 + (i - 4); };
    return {__builtin_shuffle(a, b, Index8{at(i0), at(i1), at(i2), at(i3), at(i4), at(i5), at(i6), at(i7)})};
  } else {
    return L::make(x[i0], x[i1], x[i2], x[i3], x[i4], x[i5], x[i6], x[i7]);
  }
}

// |a| (a bit operation), the larger and the smaller of a and b (b where either is NaN), lane by lane.
// (GCC makes one instruction of each; a comparison whose mask is used as a vector of integers becomes a
// comparison per lane, so there is none of those here.)
template <class L>
HINGE_FAST_INLINE L magnitude(L a) {
  constexpr long long kNoSign = 0x7fffffffffffffffLL;
  L r;
  if constexpr (std::is_same_v<L, Zmm8>) r.v = (Double8)((Index8)a.v & kNoSign);
  else
    for (int k = 0; k < 2; ++k) r.h[k] = (Double4)((Index4)a.h[k] & kNoSign);
  return r;
}
template <class L>
HINGE_FAST_INLINE L larger(L a, L b) {
  L r;
  if constexpr (std::is_same_v<L, Zmm8>) r.v = a.v > b.v ? a.v : b.v;
  else
    for (int k = 0; k < 2; ++k) r.h[k] = a.h[k] > b.h[k] ? a.h[k] : b.h[k];
  return r;
}
template <class L>
HINGE_FAST_INLINE L smaller(L a, L b) {
  L r;
  if constexpr (std::is_same_v<L, Zmm8>) r.v = a.v < b.v ? a.v : b.v;
  else
    for (int k = 0; k < 2; ++k) r.h[k] = a.h[k] < b.h[k] ? a.h[k] : b.h[k];
  return r;
}
// The area filter of the double kernels: where a triangle's area is certainly nonzero, from a component
// of its normal N computed in double-double (`component`, its high part) and perm = |a_i b_j| + |a_j b_i|
// of that component: perm > 2^-900 (below, the products' low parts may have underflowed) and |N_k| >
// 2^-90 perm (its evaluation error is a few units of 2^-106 perm: a wide margin). Positive there (a
// difference of doubles has the sign of their comparison), not positive elsewhere.
template <class L>
HINGE_FAST_INLINE L area_certainty(L perm, L component) {
  return smaller(perm - L::broadcast(0x1p-900), magnitude(component) - perm * 0x1p-90);
}
// The sum of the eight lanes, in a fixed order (NaN if any lane is).
template <class L>
HINGE_FAST_INLINE double lane_sum(L a) {
  a = a + swap_halves(a);
  a = a + permute<2, 3, 0, 1>(a);
  a = a + permute<1, 0, 3, 2>(a);
  return a.lane(0);
}
// The largest of the eight lanes (NaN-free lanes).
template <class L>
HINGE_FAST_INLINE double largest_lane(L a) {
  a = larger(a, swap_halves(a));
  a = larger(a, permute<2, 3, 0, 1>(a));
  a = larger(a, permute<1, 0, 3, 2>(a));
  return a.lane(0);
}
// Two sets of lanes side by side: the per-hinge kernel on two hinges at once (src/hinge_kernel_lanes.hpp,
// the batch of hinge_kernel.hpp). Every operation acts on both, lane by lane as on one, so each hinge
// gets exactly its bits alone, and the processor has two independent chains of operations to overlap
// (one hinge alone leaves it idle for part of its chain: hinge_kernel_double.cpp).
template <class L>
struct Twice {
  L a, b;
  static HINGE_FAST_INLINE Twice make(double a0, double a1, double a2, double a3, double b0, double b1, double b2,
                                      double b3) {
    return {L::make(a0, a1, a2, a3, b0, b1, b2, b3), L::make(a0, a1, a2, a3, b0, b1, b2, b3)};
  }
  static HINGE_FAST_INLINE Twice broadcast(double x) { return {L::broadcast(x), L::broadcast(x)}; }
  friend HINGE_FAST_INLINE Twice operator+(Twice x, Twice y) { return {x.a + y.a, x.b + y.b}; }
  friend HINGE_FAST_INLINE Twice operator-(Twice x, Twice y) { return {x.a - y.a, x.b - y.b}; }
  friend HINGE_FAST_INLINE Twice operator*(Twice x, Twice y) { return {x.a * y.a, x.b * y.b}; }
  friend HINGE_FAST_INLINE Twice operator/(Twice x, Twice y) { return {x.a / y.a, x.b / y.b}; }
  friend HINGE_FAST_INLINE Twice operator*(Twice x, double y) { return {x.a * y, x.b * y}; }
  friend HINGE_FAST_INLINE Twice operator-(Twice x) { return {-x.a, -x.b}; }
};
template <class L>
HINGE_FAST_INLINE Twice<L> fused(Twice<L> x, Twice<L> y, Twice<L> z) {
  return {fused(x.a, y.a, z.a), fused(x.b, y.b, z.b)};
}
template <class L>
HINGE_FAST_INLINE Twice<L> root(Twice<L> x) {
  return {root(x.a), root(x.b)};
}
template <int p0, int p1, int p2, int p3, class L>
HINGE_FAST_INLINE Twice<L> permute(Twice<L> x) {
  return {permute<p0, p1, p2, p3>(x.a), permute<p0, p1, p2, p3>(x.b)};
}
template <int b0, int b1, int b2, int b3, class L>
HINGE_FAST_INLINE Twice<L> blend(Twice<L> x, Twice<L> y) {
  return {blend<b0, b1, b2, b3>(x.a, y.a), blend<b0, b1, b2, b3>(x.b, y.b)};
}
template <int i0, int i1, int i2, int i3, class L>
HINGE_FAST_INLINE Twice<L> shuffle(Twice<L> x, Twice<L> y) {
  return {shuffle<i0, i1, i2, i3>(x.a, y.a), shuffle<i0, i1, i2, i3>(x.b, y.b)};
}
template <class L>
HINGE_FAST_INLINE Twice<L> swap_halves(Twice<L> x) {
  return {swap_halves(x.a), swap_halves(x.b)};
}
template <class L>
HINGE_FAST_INLINE Twice<L> magnitude(Twice<L> x) {
  return {magnitude(x.a), magnitude(x.b)};
}
template <class L>
HINGE_FAST_INLINE Twice<L> larger(Twice<L> x, Twice<L> y) {
  return {larger(x.a, y.a), larger(x.b, y.b)};
}
template <class L>
HINGE_FAST_INLINE Twice<L> smaller(Twice<L> x, Twice<L> y) {
  return {smaller(x.a, y.a), smaller(x.b, y.b)};
}
// The lanes of hinge h (0 or 1) of W = L or Twice<L> (h = 0).
template <int h, class L>
HINGE_FAST_INLINE const L& part(const L& x) {
  static_assert(h == 0);
  return x;
}
template <int h, class L>
HINGE_FAST_INLINE const L& part(const Twice<L>& x) {
  static_assert(h == 0 || h == 1);
  if constexpr (h == 0) return x.a;
  else return x.b;
}

// a times 2^k lane by lane, exactly but where a result is subnormal (the rare path of the kernel).
template <class L>
inline L scaled_by_power_of_two(L a, int k) {
  double lanes[8];
  std::memcpy(lanes, &a, sizeof lanes);
  for (double& x : lanes) x = std::ldexp(x, k);
  std::memcpy(&a, lanes, sizeof lanes);
  return a;
}
// Stores four doubles (a half) at p.
HINGE_FAST_INLINE void store4(double* p, Double4 v) { std::memcpy(p, &v, sizeof v); }

}  // namespace hinge::fast
