// The double per-hinge kernel across eight lanes (hinge/fast/hinge_kernel.hpp states what it computes;
// lanes.hpp the lane types). Included by hinge_kernel_double.cpp only, which compiles it for AVX-512,
// for AVX2 and for the baseline x86-64: the same bits on all three.
//
// Layout. Half 0 of every vector is the upper triangle (x0, x1, x2), half 1 the lower one in the
// paper's labels (x3, x1, x2); lane j of a half holds the triangle's edge f_j (lane 3 repeats f_0), and
// a vector quantity is three such vectors, its x, y and z components ("structure of arrays"):
//   F      f_j = x_{j+2} - x_{j+1} exactly, as double-doubles:  f0 = x2 - x1, f1 = x0 - x2 (x3 - x2),
//          f2 = x1 - x0 (x1 - x3)
//   C      f2 x f0 in every lane of a half: 2A n for the upper triangle, -2A~ n~ for the lower
//   X      lane j: f_j x C = (2A)^2 q_j
//   dots   lanes 0 .. 3: S = C . C = (2A)^2, L0 = f0 . f0 = l_0^2, D1 = f2 . f0, D2 = f0 . f1
// so that the three cross products X_j of a triangle, or four of its dot products, cost one vector
// operation for both triangles. Every per-triangle quantity of hinge_kernel.hpp's header (n, q_j, a_j,
// r_0) is computed in double-double (exact.hpp) and rounded to double once; eqs. (4) and (6) follow in
// double.
//
// Eq. (6) in lanes. With c = (-a_0, a_1, a_2) (eq. (4) reads grad_{x_I} theta = c_I n on each triangle),
// the upper triangle's part of block (I, J), column c, is
//   c_I (q_J n[c]) + c_J (n q_I[c])                                                       (eq. (6))
// (H00 = -S(Q_0), H10 = P_10 - Q_1, H11 = S(P_11) ..., proofs/hessian.md), and the lower triangle's is
// the same in its labels (x3, x1, x2); blocks (1, 1), (1, 2), (2, 1), (2, 2) add both triangles and
// -+ the symmetric part of N_0 + N~_0. One vector holds the upper triangle's block column in half 0 and
// the lower's in half 1 (lanes 0 .. 2: the three rows). The mirror of an entry is formed from the same
// two products (q_J[r] n[c] and n[r] q_I[c] commute) and the same sums: the Hessian is exactly
// symmetric. (Multiplying c_I n first, then by q_J, costs accuracy: worst 4.2 instead of 2.8 units of
// 2^-53 on 4000 well-shaped hinges; the grouping above is the one measured best.)
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "faithful_theta.hpp"
#include "generic_kernel.hpp"
#include "lanes.hpp"

namespace hinge::fast::detail {

template <int j, class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> spread_dd(const DoubleDoubleOf<L>& a) {
  return {spread<j>(a.hi), spread<j>(a.lo)};
}
template <int b0, int b1, int b2, int b3, class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> blend_dd(const DoubleDoubleOf<L>& a, const DoubleDoubleOf<L>& b) {
  return {blend<b0, b1, b2, b3>(a.hi, b.hi), blend<b0, b1, b2, b3>(a.lo, b.lo)};
}
template <int p0, int p1, int p2, int p3, class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> permute_dd(const DoubleDoubleOf<L>& a) {
  return {permute<p0, p1, p2, p3>(a.hi), permute<p0, p1, p2, p3>(a.lo)};
}
// Eqs. (4) and (6) are written once, for the plain kernel's lanes L and for the faithful mode's
// double-doubles of them (DoubleDoubleOf<L>, exact.hpp's arithmetic); these are the operations both need.
template <int j, class L>
HINGE_FAST_INLINE L spread_of(const L& a) {
  return spread<j>(a);
}
template <int j, class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> spread_of(const DoubleDoubleOf<L>& a) {
  return spread_dd<j>(a);
}
template <class L>
HINGE_FAST_INLINE L swapped(const L& a) {
  return swap_halves(a);
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> swapped(const DoubleDoubleOf<L>& a) {
  return {swap_halves(a.hi), swap_halves(a.lo)};
}
template <int b0, int b1, int b2, int b3, class L>
HINGE_FAST_INLINE L blend_of(const L& a, const L& b) {
  return blend<b0, b1, b2, b3>(a, b);
}
template <int b0, int b1, int b2, int b3, class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> blend_of(const DoubleDoubleOf<L>& a, const DoubleDoubleOf<L>& b) {
  return blend_dd<b0, b1, b2, b3>(a, b);
}
// a m, lane by lane, for m of -1, 0, 1 and powers of two (exact).
template <class L>
HINGE_FAST_INLINE L scaled_exactly(const L& a, const L& m) {
  return a * m;
}
template <class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> scaled_exactly(const DoubleDoubleOf<L>& a, const L& m) {
  return {a.hi * m, a.lo * m};
}
// The value rounded to double: a double-double from exact.hpp's operations is normalized (hi = fl(hi + lo)).
template <class L>
HINGE_FAST_INLINE L rounded(const L& a) {
  return a;
}
template <class L>
HINGE_FAST_INLINE L rounded(const DoubleDoubleOf<L>& a) {
  return a.hi;
}

// Lanes 0, 1, 2 of each half: lane j of a, b and c (lane 3: lane j of a).
template <int j, class L>
HINGE_FAST_INLINE L lanes_of(const L& a, const L& b, const L& c) {
  return shuffle<0, 1, 4 + j, 0>(shuffle<j, 4 + j, j, j>(a, b), c);
}
template <int j, class L>
HINGE_FAST_INLINE DoubleDoubleOf<L> lanes_of(const DoubleDoubleOf<L>& a, const DoubleDoubleOf<L>& b,
                                             const DoubleDoubleOf<L>& c) {
  return {lanes_of<j>(a.hi, b.hi, c.hi), lanes_of<j>(a.lo, b.lo, c.lo)};
}
// In lane 0 of each half: (a_0 + a_1) + a_2, and the largest of a_0, a_1, a_2.
template <class L>
HINGE_FAST_INLINE L sum_of_three(const L& a) {
  return (a + permute<1, 2, 0, 3>(a)) + permute<2, 0, 1, 3>(a);
}
template <class L>
HINGE_FAST_INLINE L largest_of_three(const L& a) {
  return larger(larger(a, permute<1, 2, 0, 3>(a)), permute<2, 0, 1, 3>(a));
}

// a b rounded once, lane by lane: the exact product of the high parts, its error and the first-order terms.
template <class L>
HINGE_FAST_INLINE L round_product(const DoubleDoubleOf<L>& a, const DoubleDoubleOf<L>& b) {
  const L p = a.hi * b.hi;
  return p + (product_error(a.hi, b.hi, p) + fused(a.hi, b.lo, a.lo * b.hi));
}

// The gradient from g[c] (lanes 0, 1, 2, 4: component c of the gradient at x0, x1, x2, x3) into
// grad[0 .. 11] (x0.x, x0.y, ..., x3.z).
template <class L>
HINGE_FAST_INLINE void store_gradient(const L g[3], double* grad) {
  if constexpr (std::is_same_v<L, Zmm8>) {
    const Double8 xy = __builtin_shuffle(g[0].v, g[1].v, Index8{0, 8, 0, 1, 9, 1, 2, 10});  // x0 y0 _ x1 y1 _ x2 y2
    const Double8 head = __builtin_shuffle(xy, g[2].v, Index8{0, 1, 8, 3, 4, 9, 6, 7});     // x0 y0 z0 x1 y1 z1 x2 y2
    const Double8 tail = __builtin_shuffle(g[0].v, g[1].v, Index8{4, 12, 4, 12, 4, 12, 4, 12});  // x3 y3 ...
    const Double4 last{g[2].v[2], tail[0], tail[1], g[2].v[4]};                                  // z2 x3 y3 z3
    std::memcpy(grad, &head, sizeof head);
    std::memcpy(grad + 8, &last, sizeof last);
  } else {
    for (int c = 0; c < 3; ++c) {
      grad[c] = g[c].lane(0);
      grad[3 + c] = g[c].lane(1);
      grad[6 + c] = g[c].lane(2);
      grad[9 + c] = g[c].lane(4);
    }
  }
}

// Eq. (6) from the two triangles' summaries in lanes (n: n[c] in every lane of a half, nv: n in lanes
// 0 .. 2; q: lane J of q[c] is q_J[c]; a: lane j is a_j; rv: r_0 in lanes 0 .. 2), into `hess` (12 x 12,
// column-major; the matrix is symmetric). T is the lanes L (the plain kernel: each product and sum
// rounded to double) or DoubleDoubleOf<L> (the faithful mode: every operation in double-double, each
// entry rounded to double once at the end). Column by column of each vertex; a column's four blocks are
// stored four doubles at a time, each store's fourth double overwritten by the next (the last block as
// the last four doubles of the column).
template <class T>
HINGE_FAST_INLINE void lanes_hessian(const T n[3], const T nv, const T q[3], const T a, const T rv, double* hess) {
  using L = decltype(rounded(a));
  const T c =
      scaled_exactly(a, L::make(-1, 1, 1, 0, -1, 1, 1, 0));  // eq. (4): grad_{x_I} theta = c_I n on each triangle
  const T cb[3] = {spread_of<0>(c), spread_of<1>(c), spread_of<2>(c)};
  // The vectors q_J with their components in lanes 0 .. 2 of each half (lane 3: don't care).
  const T qv[3] = {lanes_of<0>(q[0], q[1], q[2]), lanes_of<1>(q[0], q[1], q[2]), lanes_of<2>(q[0], q[1], q[2])};
  const T rb[3] = {spread_of<0>(rv), spread_of<1>(rv), spread_of<2>(rv)};
  const Double4 zero{0, 0, 0, 0};
  auto store_column = [](double* col, Double4 b0, Double4 b1, Double4 b2, Double4 b3) {
    store4(col, b0);
    store4(col + 3, b1);
    store4(col + 6, b2);
    store4(col + 8, __builtin_shuffle(b2, b3, Index4{2, 4, 5, 6}));
  };
  HINGE_FAST_UNROLL
  for (int k = 0; k < 3; ++k) {
    const T nq[3] = {nv * spread_of<0>(q[k]), nv * spread_of<1>(q[k]), nv * spread_of<2>(q[k])};  // n q_I[k]
    auto block = [&](int I, int J) HINGE_FAST_LAMBDA_INLINE {
      return cb[I] * (qv[J] * n[k]) + cb[J] * nq[I];
    };  // eq. (6): upper | lower
    // eq. (6): column k of x0 (H00, H10, H20, 0) and of x3 (0, H13, H23, H33: the lower triangle's H10, H20, H00).
    const L b00 = rounded(block(0, 0)), b10 = rounded(block(1, 0)), b20 = rounded(block(2, 0));
    store_column(hess + 12 * k, b00.lo4(), b10.lo4(), b20.lo4(), zero);
    store_column(hess + 12 * (9 + k), zero, b10.hi4(), b20.hi4(), b00.hi4());
    // eq. (6): columns k of x1 and x2: H0J, both triangles' H1J and H2J with -+ the symmetric part of N_0 + N~_0,
    // the lower triangle's H0J as H3J.
    const T x1 = nv * rb[k], x2 = rv * n[k];  // n r_0[k], r_0 n[k]
    const T sym = scaled_exactly((x1 + swapped(x1)) + (x2 + swapped(x2)), L::broadcast(0.5));
    HINGE_FAST_UNROLL
    for (int J = 1; J <= 2; ++J) {
      const T b1 = block(1, J), b2 = block(2, J);
      const L b0 = rounded(block(0, J));
      const T s1 = b1 + swapped(b1), s2 = b2 + swapped(b2);
      store_column(hess + 12 * (3 * J + k), b0.lo4(), rounded(J == 1 ? s1 - sym : s1 + sym).lo4(),
                   rounded(J == 2 ? s2 - sym : s2 + sym).lo4(), b0.hi4());
    }
  }
}

// Eq. (4) into grad[0 .. 11] (x0.x, ..., x3.z): grad_x0 = -a_0 n, grad_x1 = a_1 n + a~_1 n~, grad_x2 = a_2
// n + a~_2 n~, grad_x3 = -a~_0 n~, lane by lane, then interleaved. T as for lanes_hessian.
template <class T>
HINGE_FAST_INLINE void lanes_gradient(const T n[3], const T a, double* grad) {
  using L = decltype(rounded(a));
  L g[3];
  HINGE_FAST_UNROLL
  for (int c = 0; c < 3; ++c) {
    const T t = a * n[c];
    g[c] = rounded(blend_of<1, 0, 0, 0>(t + swapped(t), -t));  // lanes 0, 1, 2, 4: x0, x1, x2, x3
  }
  store_gradient(g, grad);
}

// Where the vector work writes a hinge's grad theta (12 doubles) and Hess theta (column k at hess + 12 k):
// a HingeDerivatives' arrays, or the caller's own (hinge_derivatives_into).
struct Destination {
  double* grad;
  double* hess;
};

// What the vector work leaves to the caller: the checks it could not decide, and theta's inputs.
struct LanesOutcome {
  // alone: (two hinges at once) one of them needs a rare path, so both are to be evaluated one by one
  enum Status { computed, not_finite, zero_hinge_edge, rescale, alone } status = computed;
  bool certain_upper = false, certain_lower = false;  // the filter certified the area nonzero
  bool fast_range = false;                            // in_range() (hinge_kernel.hpp)
  bool short_hinge_edge = false;                      // l_0 < 1/4 of the longest edge: the faithful mode
  bool shortish_hinge_edge = false;                   // l_0 < 1/2: the same where nearly flat or folded
  bool folded = false;                                // n . n~ < 0
  int sign = kUndecided;                              // theta's sign by the filter, or kUndecided
  int exponent = 0;                                   // the edges were scaled by 2^-exponent
  double s_minus = 0, s_plus = 0;                     // |n - n~| = 2 sin(theta/2), |n + n~| = 2 cos(theta/2)
  double tan_half_theta = 0;                          // |tan(theta / 2)|
  FaithfulTheta faithful;                             // the faithful mode's theta inputs (faithful_theta.hpp)
};

// pick12 (lanes.hpp) of each hinge's coordinates: W is L (one hinge) or Twice<L> (two).
template <class L, class W, int i0, int i1, int i2, int i3, int i4, int i5, int i6, int i7>
HINGE_FAST_INLINE W pick12_of(const double* const* y) {
  if constexpr (std::is_same_v<W, L>) return pick12<L, i0, i1, i2, i3, i4, i5, i6, i7>(y[0]);
  else return {pick12<L, i0, i1, i2, i3, i4, i5, i6, i7>(y[0]), pick12<L, i0, i1, i2, i3, i4, i5, i6, i7>(y[1])};
}

// The vector work of the kernel on B hinges (1, or 2 side by side: lanes.hpp, Twice): for each hinge h,
// grad theta and (if asked) Hess theta into out[h], the rest into the outcome o[h], which evaluate()
// (hinge_kernel_double.cpp) completes. There is no call in it (the calls to the exact predicates and atan2
// are the caller's): GCC spills every vector register of a function around any call in it. `kRescaled`
// (B = 1): the edges are first brought to M in [1, 2) by a power of two (the rare path, the outcome
// `rescale` of the common one: M outside [2^-200, 2^200], as in the generic kernel, hinge_kernel.hpp, and
// the same numbers). With B = 2, a hinge that needs a rare path (not finite, x1 == x2, rescaled) makes
// both outcomes `alone`, and nothing is written. `kFaithful` (B = 1): the faithful mode
// (hinge/fast/faithful.hpp): the per-triangle quantities stay double-doubles and eqs. (4) and (6) run in
// double-double, each output rounded once; no short-hinge-edge path is needed.
template <class L, bool kRescaled, int B = 1, bool kFaithful = false>
HINGE_FAST_INLINE void lanes_kernel(const std::array<double, 12>* const* xs, bool want_hessian, const Destination* out,
                                    LanesOutcome* o) {
  static_assert(B == 1 || (B == 2 && !kRescaled && !kFaithful));
  using W = std::conditional_t<B == 1, L, Twice<L>>;
  using D = DoubleDoubleOf<W>;
  using V = Vec<D>;           // x, y, z
  auto each = [](auto&& f) {  // f(h) for h = 0 .. B - 1, a constant
    f(std::integral_constant<int, 0>{});
    if constexpr (B == 2) f(std::integral_constant<int, 1>{});
  };
  auto rare = [&](int h, LanesOutcome::Status status) {  // true: return now
    if constexpr (B == 1) o[h].status = status;
    else o[0].status = o[1].status = LanesOutcome::alone;
    return true;
  };
  const double* x[B];
  for (int h = 0; h < B; ++h) {
    o[h] = LanesOutcome{};
    x[h] = xs[h]->data();
  }
  {
    const W v0 = pick12_of<L, W, 0, 1, 2, 3, 4, 5, 6, 7>(x), v1 = pick12_of<L, W, 4, 5, 6, 7, 8, 9, 10, 11>(x);
    const W probe = v0 * 0.0 + v1 * 0.0;  // NaN where a coordinate is not finite
    bool stop = false;
    each([&](auto h) { stop = stop || (!(lane_sum(part<h>(probe)) == 0) && rare(h, LanesOutcome::not_finite)); });
    if (stop) return;
  }
  for (int h = 0; h < B; ++h)
    if (x[h][3] == x[h][6] && x[h][4] == x[h][7] && x[h][5] == x[h][8] && rare(h, LanesOutcome::zero_hinge_edge))
      return;

  // Fig. 1: the edges e_i, exactly (two_diff): upper f0, f1, f2, f0 | lower f0, f1, f2, f0.
  auto edges = [](const double* const* y, V& F) {
    F[0] = two_diff(pick12_of<L, W, 6, 0, 3, 6, 6, 9, 3, 6>(y), pick12_of<L, W, 3, 6, 0, 3, 3, 6, 9, 3>(y));
    F[1] = two_diff(pick12_of<L, W, 7, 1, 4, 7, 7, 10, 4, 7>(y), pick12_of<L, W, 4, 7, 1, 4, 4, 7, 10, 4>(y));
    F[2] = two_diff(pick12_of<L, W, 8, 2, 5, 8, 8, 11, 5, 8>(y), pick12_of<L, W, 5, 8, 2, 5, 5, 8, 11, 5>(y));
  };
  double largest[B];  // M (infinite when a difference overflowed)
  auto largest_component = [&](const V& F) {
    const W m = larger(larger(magnitude(F[0].hi), magnitude(F[1].hi)), magnitude(F[2].hi));
    each([&](auto h) { largest[h] = largest_lane(part<h>(m)); });
  };
  V F;
  edges(x, F);
  largest_component(F);
  if constexpr (!kRescaled) {
    for (int h = 0; h < B; ++h)
      if (!(largest[h] <= 0x1p200 && largest[h] >= 0x1p-200) && rare(h, LanesOutcome::rescale)) [[unlikely]]
        return;
  } else {
    if (!(largest[0] <= std::numeric_limits<double>::max())) {
      std::array<double, 12> quarter;
      for (int i = 0; i < 12; ++i) quarter[i] = x[0][i] * 0x1p-4;
      const double* q[1] = {quarter.data()};
      edges(q, F);
      o[0].exponent = 4;
      largest_component(F);
    }
    const int shift = std::ilogb(largest[0]);  // largest > 0: x1 != x2
    for (int c = 0; c < 3; ++c)
      F[c] = {scaled_by_power_of_two(F[c].hi, -shift), scaled_by_power_of_two(F[c].lo, -shift)};
    o[0].exponent += shift;
    largest_component(F);  // in [1, 2)
  }

  // Quantities with one vector per triangle hold its components in lanes 0 .. 2 of the triangle's half
  // (lane 3: don't care): f0 and f2 rotated (for cross products), C = f2 x f0, the normals.
  const D f0_yzx = lanes_of<0>(F[1], F[2], F[0]), f0_zxy = lanes_of<0>(F[2], F[0], F[1]);
  const D f2_yzx = lanes_of<2>(F[1], F[2], F[0]), f2_zxy = lanes_of<2>(F[2], F[0], F[1]);
  const D Cv = difference_of_products(f2_yzx, f0_zxy, f2_zxy, f0_yzx);  // eq. (4)'s n: f2 x f0 = 2A n | -2A~ n~
  const V C{spread_dd<0>(Cv), spread_dd<1>(Cv), spread_dd<2>(Cv)};      // the same, component c in every lane
  const V X = cross(F, C);                                              // eq. (5): lane j (2A)^2 q_j, q_j = m_j / h_j
  V Dl, Dr;                                                             // lanes (C, f0, f2, f0) . (C, f0, f0, f1)
  HINGE_FAST_UNROLL
  for (int c = 0; c < 3; ++c) {
    Dl[c] = blend_dd<0, 1, 1, 1>(C[c], permute_dd<0, 0, 2, 0>(F[c]));
    Dr[c] = blend_dd<0, 1, 1, 1>(C[c], permute_dd<0, 0, 0, 1>(F[c]));
  }
  const D dots = dot(Dl, Dr);  // eqs. (4)-(5): S = (2A)^2, L0 = l_0^2, D1, D2 (the cosines' numerators)
  // When this fails, the results are replaced by wide_range_kernel's (hinge_kernel.hpp, in_range():
  // (2A)^2 >= 2^-140 M^4 in both triangles and l_0^2 >= 2^-500 M^2).
  each([&](auto h) {
    const double P2 = inverse_square_power_of_two(largest[h]);
    const L& S = part<h>(dots.hi);
    o[h].fast_range =
        (S.lane(0) * P2) * P2 >= 0x1p-140 && (S.lane(4) * P2) * P2 >= 0x1p-140 && S.lane(1) * P2 >= 0x1p-500;
  });
  const W one = W::broadcast(1), nothing = W::broadcast(0);
  // 1/2A and 1/l_0 start from y = 1/sqrt of estimates in double formed before the dot products (so that
  // the square root and the division overlap them), and Newton's step y (1 + e/2), e = 1 - a y^2 (a = S,
  // L0 in double-double), is folded into the products that use them, which saves its latency: with
  // relative errors of order e^2 ~ 2^-104,
  //   1/(2A)^2 = y_S^2 (1 + e_S),  K = 1/(l_0 2A) = y_S y_L (1 + (e_S + e_L)/2),  1/l_0^2 = y_L^2 (1 + e_L),
  //   n = C y_S (1 + e_S/2)
  // (exact.hpp, rsqrt_correction; y_S y_L exact, two_prod).
  const W edge_squares = F[0].hi * F[0].hi + F[1].hi * F[1].hi + F[2].hi * F[2].hi;  // lane j: |f_j|^2, roughly
  const W estimates = blend<0, 1, 1, 1>(sum_of_three(Cv.hi * Cv.hi), blend<0, 0, 1, 1>(spread<0>(edge_squares), one));
  // A hinge edge below 1/4 of the longest edge, or below 1/2 on a nearly flat or folded hinge: eq. (6)'s
  // central blocks (H11, H12, H22) then sum terms several times their result, and the rounding of the
  // per-triangle quantities to double shows (up to 9 units of 2^-53 below 1/8, 4.3 at 0.3 on nearly flat
  // hinges): such a hinge is evaluated again in the faithful mode (hinge_kernel_double.cpp, docs/numerics.md).
  if constexpr (!kFaithful)
    each([&](auto h) {
      const double l0_squared = part<h>(edge_squares).lane(0), longest = largest_lane(part<h>(edge_squares));
      o[h].short_hinge_edge = 16 * l0_squared < longest;
      o[h].shortish_hinge_edge = 4 * l0_squared < longest;
    });
  const W y = one / root(estimates);  // lanes 0, 1: y_S, y_L (2, 3: 1)
  const W half_e = rsqrt_correction(D{blend<0, 0, 1, 1>(dots.hi, one), blend<0, 0, 1, 1>(dots.lo, nothing)}, y);  // e/2
  const D yy = two_prod(permute<0, 0, 1, 1>(y), permute<0, 1, 1, 1>(y));   // y_S^2, y_S y_L, y_L^2
  const W ee = permute<0, 0, 1, 1>(half_e) + permute<0, 1, 1, 1>(half_e);  // e_S, (e_S + e_L)/2, e_L
  const D G{yy.hi, yy.lo + yy.hi * ee};  // eq. (5)'s omega_ij factors: 1/(2A)^2, K = 1/(l_0 2A), 1/l_0^2
  const D invS = spread_dd<0>(G), K = spread_dd<1>(G), RL = spread_dd<2>(G);

  const W lower_negated = W::make(1, 1, 1, 1, -1, -1, -1, -1);
  const D nw = times_corrected(Cv, spread<0>(y), spread<0>(half_e));  // n | -n~, double-double
  const W nv = nw.hi * lower_negated;                                 // n | n~ (the lower labels run clockwise)
  // The per-triangle quantities n, q_j, r_0, a_j, each rounded to double once (the faithful mode: kept in
  // double-double).
  auto summaries = [&](auto product) HINGE_FAST_LAMBDA_INLINE {
    using T = decltype(product(invS, invS));
    struct {
      T nv, n[3], q[3], rv, a;
    } s;
    if constexpr (std::is_same_v<T, W>) s.nv = nv;
    else s.nv = scaled_exactly(nw, lower_negated);
    s.n[0] = spread_of<0>(s.nv), s.n[1] = spread_of<1>(s.nv), s.n[2] = spread_of<2>(s.nv);
    HINGE_FAST_UNROLL
    for (int c = 0; c < 3; ++c) s.q[c] = product(X[c], invS);  // eq. (5): lane j q_j = m_j / h_j
    // eq. (5): N_0 = n r_0^T, r_0 = m_0 / l_0^2, with m_0 = X_0 K (never 1 / (l_0^3 2A), which can overflow)
    s.rv = product(lanes_of<0>(X[0], X[1], X[2]) * K, RL);
    // eq. (4): a_0 = l_0 / 2A, a_1 = cos(alpha_2) / h_1 = -(e_0 . e_1) / (l_0 2A), a_2 = cos(alpha_1) / h_2 = -(e_2 .
    // e_0) / (l_0 2A)
    s.a = scaled_exactly(product(permute_dd<1, 3, 2, 3>(dots), K), W::make(1, -1, -1, 0, 1, -1, -1, 0));
    return s;
  };
  const auto summary = [&]() HINGE_FAST_LAMBDA_INLINE {
    if constexpr (kFaithful) return summaries([](const D& f, const D& g) HINGE_FAST_LAMBDA_INLINE { return f * g; });
    else return summaries([](const D& f, const D& g) HINGE_FAST_LAMBDA_INLINE { return round_product(f, g); });
  }();

  // Validity: each triangle's area is certainly nonzero when some component k of C passes the area
  // filter (lanes.hpp, area_certainty) with perm_k = |f2_i f0_j| + |f2_j f0_i|. Otherwise the caller
  // decides exactly.
  {
    const W perm = magnitude(f2_yzx.hi * f0_zxy.hi) + magnitude(f2_zxy.hi * f0_yzx.hi);
    const W certain = largest_of_three(area_certainty(perm, Cv.hi));
    each([&](auto h) {
      o[h].certain_upper = part<h>(certain).lane(0) > 0;
      o[h].certain_lower = part<h>(certain).lane(4) > 0;
    });
  }
  // The sign of theta: the filter of exact.hpp (orientation_filter) on p = fl(x2 - x1), q = fl(x0 - x1),
  // r = fl(x3 - x1), the high parts of f0, -f2 and -f2~, with the same operations in the same order (so
  // the same numbers as the filter's); the rescaled path calls the filter itself (its p, q, r are the
  // differences of the unscaled coordinates). The caller decides exactly when it cannot.
  if constexpr (kRescaled) {
    double p[3], qq[3], r[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = x[0][6 + k] - x[0][3 + k];
      qq[k] = x[0][k] - x[0][3 + k];
      r[k] = x[0][9 + k] - x[0][3 + k];
    }
    double computed;
    o[0].sign = orientation_filter(p, qq, r, computed);
  } else {
    const W p = lanes_of<0>(F[0].hi, F[1].hi, F[2].hi);                                        // lanes k: p_k
    const W m1 = f2_yzx.hi * swap_halves(f2_zxy.hi), m2 = f2_zxy.hi * swap_halves(f2_yzx.hi);  // q_i r_j, q_j r_i
    const W det = sum_of_three(p * (m1 - m2)), perm = sum_of_three(magnitude(p) * (magnitude(m1) + magnitude(m2)));
    // The guard: every |p_k|, |q_k|, |r_k| zero or in [2^-300, 2^300] (the upper limit holds: M <= 2^200);
    // a t in (0, 2^-300) is one where both 2^-300 - t and t are positive.
    auto small = [](const W& v) { return smaller(W::broadcast(0x1p-300) - magnitude(v), magnitude(v)); };
    const W tiny = largest_of_three(larger(small(p), small(f2_yzx.hi)));
    each([&](auto h) {
      const double d = part<h>(det).lane(0), bound = 9.0 * 0x1p-53 * part<h>(perm).lane(0);
      const int negative = d > bound, positive = -d > bound;
      const int decided = (part<h>(tiny).lane(0) <= 0) & (part<h>(tiny).lane(4) <= 0) &
                          (negative | positive | (part<h>(perm).lane(0) == 0.0));
      o[h].sign = decided ? positive - negative : kUndecided;
    });
  }
  // theta = sgn 2 atan2(|n - n~|, |n + n~|) (Fig. 3 and eq. (12)): nw's halves are n and -n~ in
  // double-double, so their sum is n - n~ (half 0) and their difference -(n + n~) (half 1). Their squared
  // lengths are summed in double-double and rounded once; the atan2 is the caller's (libm), tan(theta/2) =
  // |n - n~| / |n + n~| the square root of their quotient.
  {
    const D t{swap_halves(nw.hi) * lower_negated, swap_halves(nw.lo) * lower_negated};
    const D s = nw + t;
    const D sq = two_prod(s.hi, s.hi);
    const W small = sq.lo + (s.hi + s.hi) * s.lo;  // the square's error and its first-order term
    const D s01 = two_sum(sq.hi, permute<1, 2, 0, 3>(sq.hi)), s012 = two_sum(s01.hi, permute<2, 0, 1, 3>(sq.hi));
    const W lengths2 = s012.hi + ((s01.lo + s012.lo) + sum_of_three(small));  // lane 0: |n - n~|^2, lane 4: |n + n~|^2
    const W lengths = root(lengths2);
    const W nn = sum_of_three(nv * swap_halves(nv));  // n . n~
    each([&](auto h) {
      o[h].s_minus = part<h>(lengths).lane(0);
      o[h].s_plus = part<h>(lengths).lane(4);
      o[h].tan_half_theta = std::sqrt(part<h>(lengths2).lane(0) / part<h>(lengths2).lane(4));
      o[h].folded = part<h>(nn).lane(0) < 0;
    });
    if constexpr (kFaithful) {
      const W low = (s01.lo + s012.lo) + sum_of_three(small);  // lengths2 = s012.hi + low, rounded
      FaithfulTheta& f = o[0].faithful;
      f.minus2 = {s012.hi.lane(0), low.lane(0)};
      f.plus2 = {s012.hi.lane(4), low.lane(4)};
      f.l0_squared = {dots.hi.lane(1), dots.lo.lane(1)};
      f.K = {K.hi.lane(0), K.lo.lane(0)};
      f.K_lower = {K.hi.lane(4), K.lo.lane(4)};
    }
  }

  // Eqs. (4) and (6), hinge by hinge.
  const auto& s = summary;
  if constexpr (kFaithful) {
    lanes_gradient(s.n, s.a, out[0].grad);
    if (want_hessian) lanes_hessian(s.n, s.nv, s.q, s.a, s.rv, out[0].hess);
  } else {
    each([&](auto h) {
      const L nh[3] = {part<h>(s.n[0]), part<h>(s.n[1]), part<h>(s.n[2])};
      lanes_gradient(nh, part<h>(s.a), out[h].grad);
      if (want_hessian) {
        const L qh[3] = {part<h>(s.q[0]), part<h>(s.q[1]), part<h>(s.q[2])};
        lanes_hessian(nh, part<h>(s.nv), qh, part<h>(s.a), part<h>(s.rv), out[h].hess);
      }
    });
  }
}

}  // namespace hinge::fast::detail
