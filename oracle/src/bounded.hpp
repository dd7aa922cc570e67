// oracle/src/bounded.hpp: double-double arithmetic that carries a rigorous bound on its error (private to
// hinge::oracle): the fast path's arithmetic (fast_path.cpp), proofs/oracle-fast-path.md.
//
// A Bounded (hi, lo, err) stands for an exact real x with |hi + lo - x| <= err; hi + lo is normalized
// (the sum ends in an exact two_sum). Each operation computes hi + lo from the operands' hi + lo as a
// double-double does, and err as the operands' errors propagated plus a bound on the operation's own
// rounding, written from the values it computed: a rounded operation's result y differs from the exact
// one by at most u |y| (u = 2^-53, round to nearest) when it does not underflow. Where an operation may
// underflow, an absolute eta = 2^-1000 is added, far above anything an underflow loses (a few units of
// 2^-1074 per operation). err itself is computed with rounding to nearest from nonnegative terms, at most
// a dozen roundings each of relative size u: multiplying by 1 + 2^-49 (16 u) keeps it an upper bound.
// So err is an upper bound at every step, and an exactly computed zero (from exact zero operands) keeps
// err = 0.
//
// Requires IEEE double with round to nearest and no contraction (the project builds with -ffp-contract=off).
#pragma once

#include <cmath>

namespace hinge::oracle::detail {

struct Bounded {
  double hi = 0, lo = 0, err = 0;
  Bounded() = default;
  explicit Bounded(double v) : hi(v) {}  // exact
  Bounded(double h, double l, double e) : hi(h), lo(l), err(e) {}
};

namespace bounded {

inline constexpr double u = 0x1p-53;
inline constexpr double inflate = 1 + 0x1p-49;
inline constexpr double eta = 0x1p-1000;
inline constexpr double tiny = 0x1p-960;  // below it, a product or a rounding error may underflow

// s + e = a + b exactly (Knuth).
inline void two_sum(double a, double b, double& s, double& e) {
  s = a + b;
  const double bb = s - a;
  e = (a - (s - bb)) + (b - bb);
}

// An upper bound on |x|, and a lower bound (positive only when x is certainly not 0).
inline double magnitude(const Bounded& a) { return (std::fabs(a.hi) + std::fabs(a.lo) + a.err) * inflate; }
inline double lower(const Bounded& a) { return (std::fabs(a.hi) - std::fabs(a.lo) - a.err) * (1 - 0x1p-50); }

}  // namespace bounded

// Known to be exactly zero (a zero computed from exact zeros: err stays 0).
inline bool is_exact_zero(const Bounded& a) { return a.hi == 0 && a.lo == 0 && a.err == 0; }

inline Bounded operator-(const Bounded& a) { return {-a.hi, -a.lo, a.err}; }

// (a.hi + b.hi) exactly as s + e; t = a.lo + b.lo and v = e + t rounded (within u |t| and u |v|); s + v
// exactly. An addition never loses more than u |result| to underflow (a sum below 2^-1022 is exact), but
// u |t| itself may underflow: eta below `tiny`.
inline Bounded operator+(const Bounded& a, const Bounded& b) {
  using namespace bounded;
  double s, e, hi, lo;
  two_sum(a.hi, b.hi, s, e);
  const double t = a.lo + b.lo, v = e + t;
  two_sum(s, v, hi, lo);
  const double m = std::fabs(t) + std::fabs(v);
  return {hi, lo, (a.err + b.err + u * m) * inflate + ((m > 0) & (m < tiny) ? eta : 0)};
}
inline Bounded operator-(const Bounded& a, const Bounded& b) { return a + (-b); }

// a.hi b.hi exactly as p + pe (a fused multiply-add); q = a.lo b.hi and c = a.hi b.lo + q rounded,
// v = pe + c rounded, a.lo b.lo left out; p + v exactly. Rounding: u (|q| + |c| + |v|) + |a.lo b.lo|.
// Propagated: |a| eb + |b| ea + ea eb. Exact (err 0) when a factor is an exact zero, or when both are
// exact doubles whose product does not underflow (then q = c = 0 and pe is exact).
inline Bounded operator*(const Bounded& a, const Bounded& b) {
  using namespace bounded;
  const double p = a.hi * b.hi, pe = std::fma(a.hi, b.hi, -p);
  const double q = a.lo * b.hi, c = std::fma(a.hi, b.lo, q), v = pe + c;
  double hi, lo;
  two_sum(p, v, hi, lo);
  const double ma = std::fabs(a.hi) + std::fabs(a.lo), mb = std::fabs(b.hi) + std::fabs(b.lo);
  const double rounding = u * (std::fabs(q) + std::fabs(c) + std::fabs(v)) + std::fabs(a.lo * b.lo);
  const double err = (ma * b.err + mb * a.err + a.err * b.err + rounding) * inflate;
  const bool zero_factor = (ma + a.err == 0) | (mb + b.err == 0);
  const bool exact_doubles = (a.lo == 0) & (b.lo == 0) & (a.err == 0) & (b.err == 0) & (ma * mb >= tiny);
  if (zero_factor | exact_doubles) return {hi, lo, 0.0};
  return {hi, lo, err + eta};
}

// A value no decision accepts (what an operation outside its domain returns).
inline Bounded undefined() { return {NAN, NAN, INFINITY}; }

// 1 / d, for d certainly not zero (bounded::lower(d) > 0; else undefined()). The approximation r (one Newton step from
// 1 / d.hi) is bounded by its residual: |r - 1/x| = |1 - r x| / |x| <= (|1 - r (d.hi + d.lo)| + |r| d.err)
// / lower(d), the residual computed as a Bounded from exact operands.
inline Bounded reciprocal(const Bounded& d) {
  using namespace bounded;
  const double low = lower(d);
  if (!(low > 0)) return undefined();
  const Bounded dd(d.hi, d.lo, 0);
  const double r0 = 1 / d.hi;
  const Bounded e0 = Bounded(1) - Bounded(r0) * dd;
  double hi, lo;
  two_sum(r0, r0 * e0.hi, hi, lo);
  const Bounded r(hi, lo, 0);
  const Bounded rho = Bounded(1) - r * dd;
  const double numerator = (std::fabs(rho.hi) + std::fabs(rho.lo) + rho.err + magnitude(r) * d.err + eta) * inflate;
  return {hi, lo, numerator / low * inflate};
}

inline Bounded operator/(const Bounded& a, const Bounded& b) { return a * reciprocal(b); }

// sqrt(x), for x certainly positive (bounded::lower(x) > 0; else undefined()): y = sqrt(x.hi), one Newton step; then
// |l - sqrt(x)| = |l^2 - x| / (l + sqrt(x)) <= (|l^2 - (x.hi + x.lo)| + x.err) / l.
inline Bounded root(const Bounded& x) {
  using namespace bounded;
  if (!(lower(x) > 0)) return undefined();
  const Bounded xx(x.hi, x.lo, 0);
  const double y = std::sqrt(x.hi);
  const Bounded rho = xx - Bounded(y) * Bounded(y);
  double hi, lo;
  two_sum(y, rho.hi / (2 * y), hi, lo);
  const Bounded l(hi, lo, 0);
  const Bounded res = l * l - xx;
  const double numerator = (std::fabs(res.hi) + std::fabs(res.lo) + res.err + x.err + eta) * inflate;
  return {hi, lo, numerator / (hi * (1 - 0x1p-50)) * inflate};
}

}  // namespace hinge::oracle::detail
