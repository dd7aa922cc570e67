// Certification of one hinge's outputs (hinge/oracle/oracle.hpp): Ziv's strategy on MPFI enclosures of
// the exact form (exact.hpp), with exact detection of zeros and of ties.
//
// Why an enclosure that rounds to one double certifies the output: rounding to nearest is monotone, so
// if both end points of an interval containing v round to the same double d, every point of it does,
// v included; d is the double nearest to v (the tie rule only matters at a midpoint, which the integer
// test below decides exactly).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "fast_path.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge_intervals.hpp"
#include "interval.hpp"

namespace hinge::oracle {

namespace detail {

std::string to_decimal_rounded(mpfr_srcptr x, mpfr_rnd_t rnd) {
  if (mpfr_zero_p(x)) return "0";
  if (mpfr_nan_p(x)) return "nan";
  if (mpfr_inf_p(x)) return mpfr_sgn(x) > 0 ? "inf" : "-inf";
  mpfr_exp_t e = 0;
  char* digits = mpfr_get_str(nullptr, &e, 10, 40, x, rnd);
  std::string s(digits);
  mpfr_free_str(digits);
  const bool negative = s[0] == '-';
  if (negative) s.erase(0, 1);
  std::string out = negative ? "-" : "";
  out += s.substr(0, 1) + "." + s.substr(1) + "e" + std::to_string(static_cast<long>(e) - 1);
  return out;
}

std::string to_decimal(mpfr_srcptr x) { return to_decimal_rounded(x, MPFR_RNDN); }

Interval quotient(const Int& num, const Int& den, const Interval& root, long shift) {
  if (sgn(num) == 0) return Interval::zero();
  return scale2(Interval(num) / (Interval(den) * root), shift);
}

Angle angle(const ExactHinge& e, const Interval& l0) {
  Angle a;
  const int ys = sgn(e.Y), xs = sgn(e.X);
  if (ys == 0) {
    // N x Nt is parallel to e0, so Y = 0 means N parallel to Nt: X = +-|N| |Nt| is not zero.
    if (xs == 0) throw std::logic_error("hinge oracle: X = Y = 0 on a non-degenerate hinge");
    if (xs > 0) {
      a.theta = Interval::zero();
      a.tan_half = Interval::zero();
      a.exactly_zero = true;
    } else {
      a.theta = Interval::pi();  // the branch cut: theta = +pi, never -pi (docs/contract.md)
      a.branch_cut = true;
    }
    return a;
  }
  const Interval r = sqrt(Interval(Int(e.nn * e.tt)));  // |N| |Nt|
  const Interval X(e.X), Y(e.Y);
  a.tan_half = xs > 0 ? Interval(Y / (l0 * (r + X))) : Interval(l0 * (r - X) / Y);  // eq. (12)
  a.theta = 2 * atan(a.tan_half);
  return a;
}

double round_to(mpfr_srcptr x, Format format) {
  if (format == Format::binary64) return mpfr_get_d(x, MPFR_RNDN);
  Real t(24);
  mpfr_set(t.get(), x, MPFR_RNDN);  // MPFR's exponent range is far wider than double's: unbounded here
  return mpfr_get_d(t.get(), MPFR_RNDN);
}

namespace {

// binary32: whether a 24-bit number lies at or above 2^128 (rounding overflows float) or is nonzero below
// 2^-126 (FLT_MIN) in magnitude. mpfr_get_exp gives e with |t| in [2^(e-1), 2^e).
bool above_float(mpfr_srcptr t) { return mpfr_regular_p(t) && mpfr_get_exp(t) >= 129; }
bool below_float(mpfr_srcptr t) { return mpfr_zero_p(t) || (mpfr_regular_p(t) && mpfr_get_exp(t) <= -126); }

Rounding round_binary64(mpfr_srcptr lo, mpfr_srcptr hi, mpfr_prec_t p) {
  Rounding r;
  r.lo = mpfr_get_d(lo, MPFR_RNDN);
  r.hi = mpfr_get_d(hi, MPFR_RNDN);
  if (r.lo != r.hi) return r;  // -0.0 == +0.0: an enclosure within [-2^-1075, 2^-1075] rounds to zero
  if (std::isinf(r.lo)) {
    r.verdict = Verdict::overflow;
    return r;
  }
  r.verdict = Verdict::rounded;
  r.value = r.lo + r.hi == 0 ? (std::signbit(r.lo) && std::signbit(r.hi) ? -0.0 : 0.0) : r.lo;
  // A point enclosure (an exactly computed value) may itself be a midpoint, which mpfr_get_d has
  // rounded to even: note it.
  if (mpfr_equal_p(lo, hi) && std::isfinite(r.value) && mpfr_cmp_d(lo, r.value) != 0) {
    Real twice_gap(p + 64);
    mpfr_sub_d(twice_gap.get(), lo, r.value, MPFR_RNDN);  // exact at this precision
    mpfr_mul_2ui(twice_gap.get(), twice_gap.get(), 1, MPFR_RNDN);
    const double toward = std::nextafter(r.value, mpfr_sgn(twice_gap.get()) > 0 ? HUGE_VAL : -HUGE_VAL);
    r.tie = std::isfinite(toward) && mpfr_cmp_d(twice_gap.get(), toward - r.value) == 0;
  }
  return r;
}

// The end points rounded to 24 bits with an unbounded exponent; the range decided on those (monotone
// rounding again: every point of the enclosure rounds between them).
Rounding round_binary32(mpfr_srcptr lo, mpfr_srcptr hi) {
  Rounding r;
  Real a(24), b(24);
  mpfr_set(a.get(), lo, MPFR_RNDN);
  mpfr_set(b.get(), hi, MPFR_RNDN);
  r.lo = mpfr_get_d(a.get(), MPFR_RNDN);  // exact within double's range
  r.hi = mpfr_get_d(b.get(), MPFR_RNDN);
  const bool same = mpfr_equal_p(a.get(), b.get()) != 0;
  if (same && mpfr_zero_p(a.get())) {  // the point zero (24-bit rounding keeps a nonzero value nonzero)
    r.verdict = Verdict::rounded;
    r.value = 0.0;
    return r;
  }
  if (above_float(a.get()) && above_float(b.get()) && mpfr_sgn(a.get()) == mpfr_sgn(b.get())) {
    r.verdict = Verdict::overflow;
    return r;
  }
  if (below_float(a.get()) && below_float(b.get())) {
    r.verdict = Verdict::underflow;
    return r;
  }
  if (!same) return r;
  r.verdict = Verdict::rounded;
  r.value = r.lo;
  // A point enclosure exactly halfway between two 24-bit numbers has 25 significant bits.
  r.tie = mpfr_equal_p(lo, hi) && mpfr_min_prec(lo) == 25;
  return r;
}

}  // namespace

Rounding round_enclosure(const Interval& v, Format format) {
  const mpfr_prec_t p = mpfi_get_prec(v.get());
  Real lo(p), hi(p);
  mpfi_get_left(lo.get(), v.get());
  mpfi_get_right(hi.get(), v.get());
  if (mpfr_nan_p(lo.get()) || mpfr_nan_p(hi.get())) return {};
  return format == Format::binary64 ? round_binary64(lo.get(), hi.get(), p) : round_binary32(lo.get(), hi.get());
}

Verdict range_of(double rounded, Format format) {
  if (format == Format::binary64) return std::isinf(rounded) ? Verdict::overflow : Verdict::rounded;
  if (std::fabs(rounded) >= 0x1p128) return Verdict::overflow;
  if (rounded != 0 && std::fabs(rounded) < 0x1p-126) return Verdict::underflow;
  return Verdict::rounded;
}

bool rounding_boundary(double a, double b, Format format, Real& m, double& at_boundary) {
  if (format == Format::binary64) {
    constexpr double largest = std::numeric_limits<double>::max();
    if (std::isfinite(a) && std::isfinite(b) && std::nextafter(a, HUGE_VAL) == b) {
      mpfr_set_d(m.get(), a, MPFR_RNDN);
      mpfr_add_d(m.get(), m.get(), b, MPFR_RNDN);  // exact: two adjacent doubles sum to at most 55 bits
      mpfr_div_2ui(m.get(), m.get(), 1, MPFR_RNDN);
    } else if ((a == largest && b == HUGE_VAL) || (a == -HUGE_VAL && b == -largest)) {
      mpfr_set_d(m.get(), largest, MPFR_RNDN);
      mpfr_add_d(m.get(), m.get(), 0x1p970, MPFR_RNDN);  // 2^1024 - 2^970, exact at 64 bits
      if (a < 0) mpfr_neg(m.get(), m.get(), MPFR_RNDN);
    } else {
      return false;
    }
    at_boundary = mpfr_get_d(m.get(), MPFR_RNDN);  // ties to even
    return true;
  }
  // binary32: a and b 24-bit numbers held exactly in doubles; zero is adjacent to no nonzero 24-bit number
  // (the exponent is unbounded).
  if (!(std::isfinite(a) && std::isfinite(b)) || a == 0 || b == 0) return false;
  Real next(24);
  mpfr_set_d(next.get(), a, MPFR_RNDN);  // exact: a is a 24-bit number
  mpfr_nextabove(next.get());
  if (mpfr_cmp_d(next.get(), b) != 0) return false;
  mpfr_set_d(m.get(), a, MPFR_RNDN);
  mpfr_add_d(m.get(), m.get(), b, MPFR_RNDN);  // exact: at most 26 bits
  mpfr_div_2ui(m.get(), m.get(), 1, MPFR_RNDN);
  at_boundary = round_to(m.get(), Format::binary32);  // ties to even
  return true;
}

double branch_cut_theta(Format format) {
  // The float nearest to pi: the compiler rounds the literal of pi_v<float> correctly.
  return format == Format::binary64 ? std::numbers::pi : static_cast<double>(std::numbers::pi_v<float>);
}

Uncertified flag(const std::string& name, const Interval& v, Format format) {
  const mpfr_prec_t p = mpfi_get_prec(v.get());
  Real lo(p), hi(p), mid(p + 1);
  mpfi_get_left(lo.get(), v.get());
  mpfi_get_right(hi.get(), v.get());
  mpfi_mid(mid.get(), v.get());
  return {name, detail::to_decimal_rounded(lo.get(), MPFR_RNDD), detail::to_decimal_rounded(hi.get(), MPFR_RNDU),
          round_to(mid.get(), format)};
}

}  // namespace detail

namespace {

using detail::Format;
using detail::Interval;
using detail::kOutputs;
using detail::Real;
using detail::Rounding;
using detail::Verdict;

// The sign of v - m for v = num 2^shift / (den sqrt(s)) and m != 0 exact, decided in integers: with v and
// m of one sign, |v| <> |m| is  num^2 2^(2 shift) <> m^2 den^2 s  (both scaled by (den sqrt(s) 2^-shift)^2).
int compare_exactly(const Int& num, const Int& den, const Int& s, long shift, mpfr_srcptr m) {
  Int M;
  const long q = mpfr_get_z_2exp(M.get_mpz_t(), m);  // m = M 2^q
  const int v_sign = sgn(num) * sgn(den);
  if (v_sign != sgn(M)) return v_sign;  // opposite sides of zero
  Int lhs = num * num, rhs = M * M * den * den * s;
  const long t = 2 * shift - 2 * q;
  if (t >= 0) lhs <<= static_cast<mp_bitcnt_t>(t);
  else rhs <<= static_cast<mp_bitcnt_t>(-t);
  const int c = cmp(lhs, rhs) * v_sign;
  return c > 0 ? 1 : c < 0 ? -1 : 0;
}

// The rounding of v = num 2^shift / (den sqrt(s)) to the format decided exactly, when its enclosure rounds
// to two adjacent values a < b: every point of the enclosure rounds to a or b, and the only boundary
// between them is their midpoint m (rounding_boundary), so the sign of v - m decides, and v = m is a tie
// (rounded to even). m is never zero. Returns false when a and b are not adjacent (the enclosure is still
// too wide); `out` is then checked against the format's range (range_of).
bool exact_round(const Int& num, const Int& den, const Int& s, long shift, double a, double b, Format format,
                 double& out, bool& tie) {
  Real m(64);
  double at_m = 0;
  if (!detail::rounding_boundary(a, b, format, m, at_m)) return false;
  const int v_minus_m = compare_exactly(num, den, s, shift, m.get());
  tie = v_minus_m == 0;
  out = v_minus_m < 0 ? a : v_minus_m > 0 ? b : at_m;
  return true;
}

// An output outside the format's range: hinge::DomainError.
[[noreturn]] void throw_outside(const char* what, Format format) {
  if (format == Format::binary64) throw_outside_double(what);
  throw DomainError(std::string(what) + " is outside the normal range of float");
}

std::string output_name(int k) {
  if (k == 0) return "theta";
  if (k <= 12) return "grad[" + std::to_string(k - 1) + "]";
  return "hess[" + std::to_string(k - 13) + "]";
}

}  // namespace

namespace {

// The outputs in the order theta, grad[0..11], hess[0..143] (fast_path.hpp) into `out`.
void set_outputs(const std::array<double, kOutputs>& value, CertifiedTheta& out) {
  out.theta = value[0];
  std::copy(value.begin() + 1, value.begin() + 13, out.grad.begin());
  std::copy(value.begin() + 13, value.end(), out.hess.begin());
}

// Stages 1 and 2 for the outputs not yet `done` (the fast path's decisions, if any).
CertifiedTheta certify_rest(const ExactHinge& e, const Options& options, std::array<bool, kOutputs> done,
                            std::array<double, kOutputs> value) {
  if (!e.has_hessian) throw std::invalid_argument("certify: the exact hinge was computed without its Hessian");
  constexpr int count = kOutputs;
  CertifiedTheta out;
  out.path = Path::exact;
  out.exact_bits = e.max_bits();
  int remaining = static_cast<int>(std::count(done.begin(), done.end(), false));
  auto settle = [&](int k, double v) {
    done[k] = true;
    value[k] = v;
    --remaining;
  };
  // Exactly zero outputs need no precision at all.
  for (int k = 0; k < 12; ++k)
    if (!done[1 + k] && sgn(e.g[k]) == 0) settle(1 + k, 0.0);
  for (int k = 0; k < 144; ++k)
    if (!done[13 + k] && sgn(e.h[k]) == 0) settle(13 + k, 0.0);
  const Format format = options.binary32 ? Format::binary32 : Format::binary64;
  if (!done[0] && sgn(e.Y) == 0) settle(0, sgn(e.X) > 0 ? 0.0 : detail::branch_cut_theta(format));  // +pi rounded
  if (remaining > 0) out.path = Path::interval;

  const unsigned cap = std::max(options.max_bits, options.start_bits);
  for (unsigned bits = std::max(53u, options.start_bits); remaining > 0; bits *= 2) {
    if (bits > cap) bits = cap;
    out.bits = bits;
    detail::WorkingPrecision precision(bits);
    const Interval l0 = sqrt(Interval(e.s));
    const Interval g_scale = Interval(e.g_den) * l0, h_scale = Interval(e.h_den) * l0;
    std::array<Interval, count> enclosure;
    for (int k = 0; k < count; ++k) {
      if (done[k]) continue;
      const bool is_grad = k >= 1 && k <= 12;
      const Int* num = k == 0 ? nullptr : is_grad ? &e.g[k - 1] : &e.h[k - 13];
      const Int& den = is_grad ? e.g_den : e.h_den;
      const long shift = is_grad ? e.F : 2 * e.F;
      if (k == 0) enclosure[k] = detail::angle(e, l0).theta;
      else enclosure[k] = scale2(Interval(*num) / (is_grad ? g_scale : h_scale), shift);
      const char* what = k == 0 ? "theta" : is_grad ? "the gradient" : "the Hessian";
      const Rounding r = detail::round_enclosure(enclosure[k], format);
      if (r.verdict == Verdict::overflow || r.verdict == Verdict::underflow) throw_outside(what, format);
      if (r.verdict == Verdict::rounded) {
        settle(k, r.value);
        if (r.tie) ++out.ties;
        continue;
      }
      // grad and Hess entries are square roots of rationals: rounding them is decidable exactly.
      double rounded = 0;
      bool tie = false;
      if (k > 0 && exact_round(*num, den, e.s, shift, r.lo, r.hi, format, rounded, tie)) {
        if (detail::range_of(rounded, format) != Verdict::rounded) throw_outside(what, format);
        settle(k, rounded);
        if (tie) ++out.ties;
        ++out.decided_exactly;
      }
    }
    if (remaining > 0 && bits >= cap) {
      for (int k = 0; k < count; ++k)
        if (!done[k]) {
          out.uncertified.push_back(detail::flag(output_name(k), enclosure[k], format));
          value[k] = out.uncertified.back().nearest;
        }
      break;
    }
  }
  set_outputs(value, out);
  return out;
}

}  // namespace

CertifiedTheta certify(const ExactHinge& e, const Options& options) { return certify_rest(e, options, {}, {}); }

CertifiedTheta certified_theta_derivatives(const std::array<double, 12>& x, const Options& options) {
  // The fast path decides roundings to double only.
  if (!options.fast_path || options.binary32) return certify(exact_hinge(x, true), options);
  const detail::FastDecisions fast = detail::fast_path(x);
  if (fast.count < kOutputs) return certify_rest(exact_hinge(x, true), options, fast.decided, fast.value);
  CertifiedTheta out;
  out.path = Path::fast;
  set_outputs(fast.value, out);
  return out;
}

const char* path_name(Path p) {
  switch (p) {
    case Path::fast: return "fast";
    case Path::exact: return "exact";
    case Path::interval: return "interval";
  }
  return "?";
}

}  // namespace hinge::oracle
