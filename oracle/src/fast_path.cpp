// The certified oracle's fast path (fast_path.hpp; the proof: proofs/oracle-fast-path.md).
#include "fast_path.hpp"

#include <mpfr.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

#include "bounded.hpp"
#include "exact_form.hpp"

namespace hinge::oracle::detail {

using bounded::inflate;
using bounded::lower;

// Whether every real within v.err of v.hi + v.lo rounds to the double v.hi, and the double (v.hi 2^scale)
// is that of every real of the interval scaled by 2^scale: the interval lies strictly inside v.hi's
// rounding interval (half the gap to each neighbour; the gap below a power of two is half the gap above),
// and v.hi 2^scale is far from underflow and overflow, where rounding commutes with the scaling. An
// exactly known zero (err 0) is +0, as the exact stage gives it.
bool decide(const Bounded& v, int scale, double& out) {
  if (!(std::isfinite(v.hi) && std::isfinite(v.lo) && std::isfinite(v.err))) return false;
  if (v.hi == 0) {
    if (v.lo != 0 || v.err != 0) return false;
    out = 0.0;
    return true;
  }
  // |hi| = 1.f 2^e with e in [-900, 900] and e + scale in [-1021, 1021]: the gap above is 2^(e - 52),
  // the gap below the same, or half of it when f = 0.
  const auto bits = std::bit_cast<std::uint64_t>(v.hi);
  const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
  if (e < -900 || e > 900 || e + scale < -1021 || e + scale > 1021) return false;
  const bool power_of_two = (bits & ((std::uint64_t{1} << 52) - 1)) == 0;
  const double half_gap = power_of_two ? std::bit_cast<double>(static_cast<std::uint64_t>(e - 54 + 1023) << 52)
                                       : std::bit_cast<double>(static_cast<std::uint64_t>(e - 53 + 1023) << 52);
  if ((std::fabs(v.lo) + v.err) * inflate >= half_gap) return false;
  // hi 2^scale: the exponent field replaced (exact; normal by the range above).
  constexpr std::uint64_t exponent_field = std::uint64_t{0x7ff} << 52;
  out = std::bit_cast<double>((bits & ~exponent_field) | (static_cast<std::uint64_t>(e + scale + 1023) << 52));
  return true;
}

namespace {

// What the arctangent needs, computed once with MPFR at 256 bits and rounded to double-doubles: atan(k/64)
// for k = 0..64, pi/2, and 1/(2j + 1) for the series (bounded reciprocals). A double-double v = hi + lo
// rounded from a 256-bit value V is within |lo| 2^-53 + |V| 2^-255 of the exact value.
struct ArctanTable {
  std::array<Bounded, 65> atan_k;
  Bounded half_pi;
  std::array<Bounded, 9> odd_inverse;
  ArctanTable() {
    mpfr_t v;
    mpfr_init2(v, 256);
    auto take = [&v] {
      const double hi = mpfr_get_d(v, MPFR_RNDN);
      mpfr_sub_d(v, v, hi, MPFR_RNDN);  // exact at 256 bits
      const double lo = mpfr_get_d(v, MPFR_RNDN);
      return Bounded(hi, lo, (std::fabs(lo) * 0x1p-53 + std::fabs(hi) * 0x1p-254) * inflate);
    };
    for (int k = 0; k <= 64; ++k) {
      mpfr_set_ui(v, static_cast<unsigned long>(k), MPFR_RNDN);
      mpfr_div_2ui(v, v, 6, MPFR_RNDN);
      mpfr_atan(v, v, MPFR_RNDN);
      atan_k[k] = take();
    }
    mpfr_const_pi(v, MPFR_RNDN);
    mpfr_div_2ui(v, v, 1, MPFR_RNDN);
    half_pi = take();
    mpfr_clear(v);
    for (int j = 0; j < 9; ++j) odd_inverse[j] = reciprocal(Bounded(2.0 * j + 1));
  }
};

// atan(t), bounded: t < 0 by symmetry, t > 1 as pi/2 - atan(1/t); then a in [0, 1] is c = k/64 (the
// nearest) plus atan(z), z = (a - c) / (1 + a c), |z| <= 1/128, by its series through z^17, whose
// remainder is below |z|^19 / 19 (alternating, decreasing).
Bounded arctan(const Bounded& t) {
  static const ArctanTable table;
  const bool negative = t.hi < 0;
  const bool inverted = std::fabs(t.hi) > 1;
  Bounded a = negative ? -t : t;
  if (inverted) a = reciprocal(a);
  if (!(std::isfinite(a.hi) && a.hi >= 0 && a.hi <= 1)) return undefined();
  const int k = static_cast<int>(std::nearbyint(a.hi * 64));
  const Bounded c(k / 64.0);
  const Bounded z = (a - c) / (Bounded(1) + a * c);
  const Bounded p = z * z;
  Bounded s = table.odd_inverse[8];
  for (int j = 7; j >= 0; --j) s = table.odd_inverse[j] - p * s;
  Bounded r = z * s;
  const double mz = bounded::magnitude(z), m2 = mz * mz, m4 = m2 * m2, m8 = m4 * m4, m16 = m8 * m8;
  r.err = (r.err + m16 * m2 * mz / 16) * inflate + bounded::eta;
  r = table.atan_k[k] + r;
  if (inverted) r = table.half_pi - r;
  return negative ? -r : r;
}

// The normal of a triangle with edges a + b + c = 0 (cyclic): a x b = b x c = c x a, exactly. The two
// shortest edges meet at the largest angle, whose sine is the largest, so their cross product cancels
// least: on a needle with one short edge (a spike, a short hinge edge) it does not cancel at all. Upper
// triangle: (e0, e1, e2) gives N = (x1 - x0) x (x2 - x0); lower: (-e~1, -e0, -e~2) = (x2 - x3, x1 - x2,
// x3 - x1) gives Nt = (x2 - x3) x (x1 - x3) (docs/contract.md).
V3<Bounded> normal(const V3<Bounded>& a, const V3<Bounded>& b, const V3<Bounded>& c) {
  auto length2 = [](const V3<Bounded>& v) { return v[0].hi * v[0].hi + v[1].hi * v[1].hi + v[2].hi * v[2].hi; };
  const double la = length2(a), lb = length2(b), lc = length2(c);
  if (la >= lb && la >= lc) return form::cross(b, c);  // a the longest
  if (lb >= lc) return form::cross(c, a);              // b the longest
  return form::cross(a, b);
}

}  // namespace

namespace {

// The exact form of x in the bounded arithmetic, from its edges scaled by 2^-E; l0 = |e0| (scaled).
struct Evaluated {
  Form<Bounded> f;
  Bounded l0;
  Bounded g_inverse, h_inverse;  // 1 / (g_den l0), 1 / (h_den l0) (with the Hessian only)
  int E = 0;
};

// Nothing when the hinge may be degenerate (the exact stage decides and gives the error) or lies outside
// the range where the scaling is exact.
std::optional<Evaluated> evaluate(const std::array<double, 12>& x, bool with_hessian) {
  for (double c : x)
    if (!std::isfinite(c) || std::fabs(c) > 0x1p1000) return std::nullopt;
  // The edges exactly, as double-doubles (a difference of two doubles is a two_sum).
  std::array<double, 15> hi{}, lo{};
  const int from[5] = {2, 0, 1, 3, 1}, to[5] = {1, 2, 0, 2, 3};  // e0 = x2 - x1, e1, e2, e~1, e~2 (Fig. 1)
  double largest = 0;
  for (int k = 0; k < 5; ++k)
    for (int c = 0; c < 3; ++c) {
      bounded::two_sum(x[3 * from[k] + c], -x[3 * to[k] + c], hi[3 * k + c], lo[3 * k + c]);
      largest = std::max(largest, std::fabs(hi[3 * k + c]));
    }
  if (largest == 0) return std::nullopt;
  // Scale by 2^-E so that the largest component lies in [1/2, 1): outputs then scale back exactly
  // (grad by 2^-E, Hess by 2^-2E; theta does not change). A part the scaling would round: not here.
  Evaluated v;
  v.E = std::ilogb(largest) + 1;
  Edges<Bounded> e;
  std::array<V3<Bounded>*, 5> edge = {&e.e0, &e.e1, &e.e2, &e.et1, &e.et2};
  for (int k = 0; k < 15; ++k) {
    const double h = std::ldexp(hi[k], -v.E), l = std::ldexp(lo[k], -v.E);
    if (std::ldexp(h, v.E) != hi[k] || std::ldexp(l, v.E) != lo[k]) return std::nullopt;
    (*edge[k / 3])[k % 3] = Bounded(h, l, 0);
  }
  const V3<Bounded> N = normal(e.e0, e.e1, e.e2), Nt = normal(form::neg(e.et1), form::neg(e.e0), form::neg(e.et2));
  Form<Bounded>& f = v.f;
  f.nn = form::dot(N, N);
  f.tt = form::dot(Nt, Nt);
  if (!(lower(f.nn) > 0 && lower(f.tt) > 0)) return std::nullopt;  // possibly degenerate
  fill_form(e, N, Nt, f, with_hessian);
  if (!(lower(f.s) > 0)) return std::nullopt;
  v.l0 = root(f.s);
  if (with_hessian) {
    v.g_inverse = reciprocal(f.g_den * v.l0);
    v.h_inverse = reciprocal(f.h_den * v.l0);
  }
  return v;
}

// t = tan(theta / 2) and theta = atan2(Y / l0, X) where Y is certainly not zero, by the half-angle forms
// that do not cancel (eq. (12)): X >= 0: t = Y / (l0 (r + X)), else t = l0 (r - X) / Y, r = |N| |Nt| (both
// hold for any X; the choice only avoids cancellation); theta = 2 atan(t). Both undefined() elsewhere.
void angle(const Evaluated& v, Bounded& theta, Bounded& t) {
  const Form<Bounded>& f = v.f;
  theta = t = undefined();
  if (!(lower(f.Y) > 0)) return;
  const Bounded r = root(f.nn * f.tt);
  t = f.X.hi >= 0 ? f.Y / (v.l0 * (r + f.X)) : (v.l0 * (r - f.X)) / f.Y;
  if (std::isfinite(t.hi) && lower(t) > 0) theta = Bounded(2.0) * arctan(t);
}

// v 2^p; a part that leaves the range of double is undefined(), one that underflows adds its loss.
Bounded scaled(const Bounded& v, int p) {
  if (is_exact_zero(v)) return v;  // an exact zero stays one
  const Bounded s(std::ldexp(v.hi, p), std::ldexp(v.lo, p), std::ldexp(v.err, p) * inflate + 0x1p-1074);
  if (!(std::isfinite(s.hi) && std::isfinite(s.lo) && std::isfinite(s.err))) return undefined();
  return s;
}

}  // namespace

FastDecisions fast_path(const std::array<double, 12>& x) {
  FastDecisions d;
  const std::optional<Evaluated> v = evaluate(x, true);
  if (!v) return d;
  const Form<Bounded>& f = v->f;
  const int E = v->E;
  const Bounded &g_inverse = v->g_inverse, &h_inverse = v->h_inverse;
  auto settle = [&d](int k, bool decided) {
    d.decided[k] = decided;
    d.count += decided;
  };
  for (int k = 0; k < 12; ++k) settle(1 + k, decide(f.g[k] * g_inverse, -E, d.value[1 + k]));
  for (int p = 0; p < 12; ++p)  // the upper triangle, and its mirror (h is exactly symmetric: exact_form.hpp)
    for (int q = p; q < 12; ++q) {
      settle(13 + 12 * p + q, decide(f.h[12 * p + q] * h_inverse, -2 * E, d.value[13 + 12 * p + q]));
      if (q != p) {
        d.value[13 + 12 * q + p] = d.value[13 + 12 * p + q];
        settle(13 + 12 * q + p, d.decided[13 + 12 * p + q]);
      }
    }
  // theta; Y exactly 0 is theta = 0 (X > 0) or the branch cut, +pi rounded (X < 0; docs/contract.md).
  if (is_exact_zero(f.Y)) {
    d.value[0] = f.X.hi > 0 ? 0.0 : std::numbers::pi;
    settle(0, lower(f.X) > 0);
  } else {
    Bounded theta, t;
    angle(*v, theta, t);
    settle(0, decide(theta, 0, d.value[0]));
  }
  return d;
}

std::optional<BoundedHinge> bounded_hinge(const std::array<double, 12>& x, bool with_derivatives) {
  const std::optional<Evaluated> v = evaluate(x, with_derivatives);
  if (!v) return std::nullopt;
  const Form<Bounded>& f = v->f;
  BoundedHinge b;
  if (is_exact_zero(f.Y) && f.X.hi > 0 && lower(f.X) > 0) {
    b.theta = b.tan_half = Bounded(0.0);  // exactly flat
  } else {
    angle(*v, b.theta, b.tan_half);
    if (!std::isfinite(b.theta.hi)) return std::nullopt;  // the branch cut, or Y not certainly nonzero
  }
  // Algorithm 1: a = 3 |e_bar|^2 / A_bar = 6 s / (|N| + |Nt|): the scaling cancels.
  b.a = Bounded(6.0) * (f.s / (root(f.nn) + root(f.tt)));
  if (!with_derivatives) return b;
  for (int k = 0; k < 12; ++k) b.grad[k] = scaled(f.g[k] * v->g_inverse, -v->E);
  for (int p = 0; p < 12; ++p)  // the upper triangle, and its mirror (h is exactly symmetric)
    for (int q = p; q < 12; ++q)
      b.hess[12 * q + p] = b.hess[12 * p + q] = scaled(f.h[12 * p + q] * v->h_inverse, -2 * v->E);
  return b;
}

}  // namespace hinge::oracle::detail
