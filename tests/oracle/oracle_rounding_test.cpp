// The fast path's rounding decision (oracle/src/fast_path.hpp: decide; proofs/oracle-fast-path.md, section 4)
// where rounding is delicate. A Bounded (hi, lo, err) stands for a real within err of hi + lo; decide may give a
// double only when every real of [hi + lo - err, hi + lo + err], times 2^scale, rounds to it. The rounding interval
// of a double d reaches half the gap to each neighbour, and below a power of two 2^e the gap is half the gap above:
// the rounding interval of 2^e is [2^e - 2^(e-54), 2^e + 2^(e-53)]. Checked here:
//
// - the decision itself, against the exact rounding of the interval's two end points (MPFR, exact at 256 bits;
//   rounding is monotone, so the interval rounds to one double exactly when its end points do): just below and
//   just above powers of two, their negative mirrors, exact midpoints (ties to even), near underflow (scaled
//   results at 2^-1022 and subnormal), near overflow, zeros and intervals straddling zero, non-finite parts;
//   that it decides whatever lies well inside a rounding interval in its range (its contract, fast_path.hpp);
// - end to end, one hinge (certified_theta_derivatives) and one mesh (certified_mesh, tan energy) whose exact
//   output lies below the midpoint under a power of two by less than the double-double can hold: the fast path's
//   own approximation then lands on the power of two, and a decision taking the gap above on both sides of it
//   would give the power of two instead of the double below. The fast path must give the enclosures' doubles.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "hinge/core/mesh.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"
#include "src/fast_path.hpp"
#include "support/same_results.hpp"

namespace hinge::oracle {
namespace {

using detail::Bounded;
using X12 = std::array<double, 12>;

Options without_fast_path() {
  Options o;
  o.fast_path = false;
  return o;
}

// 256 bits hold hi + lo +- err exactly for every interval built here (all their bits lie within 120 bits of hi's
// leading bit); each operation's exactness is checked (MPFR's ternary value).
struct Real {
  mpfr_t v;
  explicit Real(mpfr_prec_t bits = 256) { mpfr_init2(v, bits); }
  ~Real() { mpfr_clear(v); }
  Real(const Real&) = delete;
  Real& operator=(const Real&) = delete;
};

// x rounded to binary64, ties to even, with IEEE's subnormals, zeros and overflow (mpfr_get_d; checked by
// TheYardstickRoundsAsBinary64Does).
double nearest(const Real& x) { return mpfr_get_d(x.v, MPFR_RNDN); }

// hi + lo + sign err, times 2^scale, exactly.
void end_point(const Bounded& v, int sign, int scale, Real& x) {
  int inexact = mpfr_set_d(x.v, v.hi, MPFR_RNDN);
  inexact |= mpfr_add_d(x.v, x.v, v.lo, MPFR_RNDN);
  inexact |= sign > 0 ? mpfr_add_d(x.v, x.v, v.err, MPFR_RNDN) : mpfr_sub_d(x.v, x.v, v.err, MPFR_RNDN);
  inexact |= mpfr_mul_2si(x.v, x.v, scale, MPFR_RNDN);
  if (inexact != 0) ADD_FAILURE() << "end point not exact at 256 bits";
}

std::string show(const Bounded& v, int scale) {
  std::ostringstream s;
  s << std::hexfloat << "(hi " << v.hi << ", lo " << v.lo << ", err " << v.err << ") scale " << std::dec << scale;
  return s.str();
}

// The double every real of the interval times 2^scale rounds to, if there is one (both end points round to the
// same double, bit for bit: an interval straddling zero has end points rounding to -0 and +0 or beyond).
std::optional<double> exact_rounding(const Bounded& v, int scale) {
  Real a, b;
  end_point(v, -1, scale, a);
  end_point(v, +1, scale, b);
  const double ra = nearest(a), rb = nearest(b);
  if (!test::same_double(ra, rb)) return std::nullopt;
  return ra;
}

// decide's verdict is sound: when it gives a double, every real of the interval rounds to that double (and it is
// finite: an output that rounds to infinity is an error, never a decision).
::testing::AssertionResult sound(const Bounded& v, int scale) {
  double out = 0;
  if (!detail::decide(v, scale, out)) return ::testing::AssertionSuccess();
  const std::optional<double> exact = exact_rounding(v, scale);
  if (exact && std::isfinite(*exact) && test::same_double(*exact, out)) return ::testing::AssertionSuccess();
  std::ostringstream s;
  s << std::hexfloat << show(v, scale) << ": decided " << out << ", but ";
  if (!exact) {
    Real a, b;
    end_point(v, -1, scale, a);
    end_point(v, +1, scale, b);
    s << "its end points round to " << nearest(a) << " and " << nearest(b);
  } else {
    s << "it rounds to " << *exact;
  }
  return ::testing::AssertionFailure() << s.str();
}

bool decided(const Bounded& v, int scale = 0) {
  double out = 0;
  return detail::decide(v, scale, out);
}

double decision(const Bounded& v, int scale = 0) {
  double out = std::nan("");
  return detail::decide(v, scale, out) ? out : std::nan("");
}

bool power_of_two(double d) {
  return d != 0 && std::isfinite(d) && (std::bit_cast<std::uint64_t>(d) & ((std::uint64_t{1} << 52) - 1)) == 0;
}

// Intervals around the double d: lo in steps of q = 2^(e-57) (an eighth of the half-gap below a power of two 2^e,
// a sixteenth of the other half-gaps), err from 0 to twice the half-gap above, each also 2^-30 (relative) short
// of and beyond its step, so that the end points fall just inside, on and just outside the rounding interval of d
// and of its neighbours.
std::vector<Bounded> intervals_around(double d) {
  std::vector<Bounded> out;
  const int e = std::ilogb(d);
  const double q = std::ldexp(1.0, e - 57);
  for (int k = -20; k <= 36; ++k)
    for (int m : {0, 1, 3, 4, 7, 8, 12, 16, 32})
      for (double f : {1.0, 1 - 0x1p-30, 1 + 0x1p-30}) {
        if (m == 0 && f != 1.0) continue;
        out.push_back(Bounded(d, k * q, m * q * f));
        out.push_back(Bounded(d, -k * q, m * q * f));
      }
  return out;
}

// The doubles where rounding is delicate, at 2^e and of both signs: the power of two, its neighbours (the one
// below has the gap below 2^e on both sides), and one inside the binade.
std::vector<double> anchors(const std::vector<int>& exponents) {
  std::vector<double> out;
  for (int e : exponents)
    for (double sign : {1.0, -1.0}) {
      const double p = sign * std::ldexp(1.0, e);
      out.insert(out.end(), {p, std::nextafter(p, 0.0), std::nextafter(p, sign * HUGE_VAL), 1.5 * p});
    }
  return out;
}

TEST(OracleRounding, TheYardstickRoundsAsBinary64Does) {
  // The exact rounding these tests hold decide to: ties to even, the gap halved below a power of two, subnormals,
  // overflow at 2^1024 - 2^970.
  auto at = [](std::initializer_list<std::pair<double, int>> terms) {  // sum of c 2^k, exactly
    Real x(2200);
    mpfr_set_zero(x.v, +1);
    for (const auto& [c, k] : terms) {
      Real t(2200);
      mpfr_set_d(t.v, c, MPFR_RNDN);
      mpfr_mul_2si(t.v, t.v, k, MPFR_RNDN);
      mpfr_add(x.v, x.v, t.v, MPFR_RNDN);
    }
    return nearest(x);
  };
  EXPECT_EQ(at({{1, 0}, {-1, -54}}), 1.0);                          // the midpoint below 1: ties to even
  EXPECT_EQ(at({{1, 0}, {-1, -54}, {-1, -200}}), 1 - 0x1p-53);      // just below it
  EXPECT_EQ(at({{1, 0}, {-1, -54}, {1, -200}}), 1.0);               // just above it
  EXPECT_EQ(at({{1, 0}, {1, -53}}), 1.0);                           // the midpoint above 1
  EXPECT_EQ(at({{1, 0}, {1, -53}, {1, -200}}), 1 + 0x1p-52);        // a full half-gap above is needed
  EXPECT_EQ(at({{1, 0}, {3, -53}}), 1 + 0x1p-51);                   // a tie between odd and even
  EXPECT_EQ(at({{1, -1075}}), 0.0);                                 // half the smallest subnormal: to 0
  EXPECT_FALSE(std::signbit(at({{1, -1075}})));                     // +0
  EXPECT_EQ(at({{1, -1075}, {1, -1200}}), 0x1p-1074);               // just above it: up
  EXPECT_EQ(at({{3, -1075}}), 0x1p-1073);                           // 1.5 units: to the even 2
  EXPECT_EQ(at({{1, -1022}, {-1, -1075}}), 0x1p-1022);              // below 2^-1022 the gap is 2^-1074,
  EXPECT_EQ(at({{1, -1022}, {-3, -1076}}), 0x1p-1022 - 0x1p-1074);  // not halved
  EXPECT_EQ(at({{std::numeric_limits<double>::max(), 0}, {1, 970}, {-1, 900}}), std::numeric_limits<double>::max());
  EXPECT_EQ(at({{std::numeric_limits<double>::max(), 0}, {1, 970}}), HUGE_VAL);  // 2^1024 - 2^970: overflows
}

TEST(OracleRounding, JustBelowAPowerOfTwoTheRoundingIntervalReachesOnlyHalfAGapDown) {
  // Below p = 2^e the neighbour is p - 2^(e-53), so the reals that round to p reach down to p - 2^(e-54) only.
  // An interval entirely within (p - 2^(e-54), p] rounds to p and is decided (it is short of the boundary by
  // 2^-20 of the half-gap, far more than the 2^-49 decide keeps for its own rounding); one reaching 2^-20 of the
  // half-gap below p - 2^(e-54) holds reals that round to the double below and must not be decided: a decision
  // that took the gap above (2^(e-53)) on both sides would decide it as p. Also negated.
  for (int e : {-900, -100, -54, -1, 0, 1, 53, 100, 900})
    for (double sign : {1.0, -1.0}) {
      const double p = sign * std::ldexp(1.0, e), half_gap = std::ldexp(1.0, e - 54);
      const Bounded inside(p, -sign * half_gap / 2, half_gap / 2 * (1 - 0x1p-20));
      const Bounded reaching(p, -sign * half_gap / 2, half_gap / 2 * (1 + 0x1p-20));
      ASSERT_EQ(exact_rounding(inside, 0), p) << show(inside, 0);
      ASSERT_FALSE(exact_rounding(reaching, 0)) << show(reaching, 0);
      EXPECT_EQ(decision(inside), p) << show(inside, 0);
      EXPECT_FALSE(decided(reaching)) << show(reaching, 0);
      // The same with the approximation itself on the wrong side of the midpoint: hi + lo = p - half_gap exactly
      // (a tie, so hi = p), the exact value anywhere within err of it.
      const Bounded on_midpoint(p, -sign * half_gap, std::ldexp(half_gap, -40));
      EXPECT_FALSE(decided(on_midpoint)) << show(on_midpoint, 0);
      EXPECT_TRUE(sound(on_midpoint, 0));
      // Scaled back by 2^scale (the gradient's 2^-E, the Hessian's 2^-2E): the same decision at 2^(e + scale).
      for (int scale : {-100, 100}) {
        EXPECT_EQ(decision(inside, scale), std::ldexp(p, scale)) << show(inside, scale);
        EXPECT_FALSE(decided(reaching, scale)) << show(reaching, scale);
      }
    }
}

TEST(OracleRounding, JustAboveAPowerOfTwoNothingBeyondTheFullHalfGapIsDecided) {
  // Above p = 2^e the half-gap is 2^(e-53): within 2^(e-54) (the smaller half-gap, which decide takes on both
  // sides) an interval is decided; one reaching past p + 2^(e-53) holds reals rounding to the double above and is
  // not; in between it rounds to p, and decide may leave it (sound either way). Also negated.
  for (int e : {-900, -1, 0, 1, 900})
    for (double sign : {1.0, -1.0}) {
      const double p = sign * std::ldexp(1.0, e), below = std::ldexp(1.0, e - 54), above = 2 * below;
      const Bounded inside(p, sign * below / 2, below / 2 * (1 - 0x1p-20));
      const Bounded up_to_the_full_half_gap(p, sign * above / 2, above / 2 * (1 - 0x1p-20));
      const Bounded past(p, sign * above / 2, above / 2 * (1 + 0x1p-20));
      EXPECT_EQ(decision(inside), p) << show(inside, 0);
      ASSERT_EQ(exact_rounding(up_to_the_full_half_gap, 0), p);
      EXPECT_TRUE(sound(up_to_the_full_half_gap, 0));
      ASSERT_FALSE(exact_rounding(past, 0));
      EXPECT_FALSE(decided(past)) << show(past, 0);
    }
}

TEST(OracleRounding, ExactMidpointsAreNeverDecidedToTheOddNeighbour) {
  // A real exactly halfway between two doubles rounds to the even one. With err = 0 decide may know the value
  // exactly; it may then leave it or give the even double, never the odd one. With any err > 0 the interval
  // holds reals on both sides of the midpoint, and it must leave it. Each midpoint is written with either
  // neighbour as hi (only one of them is hi + lo rounded, but decide's verdict must be sound for both).
  struct Midpoint {
    double odd, even;
  };
  std::vector<Midpoint> midpoints;
  for (int e : {-900, -1, 0, 1, 52, 900})
    for (double sign : {1.0, -1.0}) {
      const double p = sign * std::ldexp(1.0, e);
      midpoints.push_back({std::nextafter(p, 0.0), p});                                            // below 2^e
      midpoints.push_back({std::nextafter(p, sign * HUGE_VAL), p});                                // above 2^e
      midpoints.push_back({std::nextafter(p, sign * HUGE_VAL),                                     // inside
                           std::nextafter(std::nextafter(p, sign * HUGE_VAL), sign * HUGE_VAL)});  // the binade
    }
  for (const Midpoint& m : midpoints) {
    const double half = (m.even - m.odd) / 2;  // exact: the gap is a power of two far above the subnormals
    for (const Bounded& v : {Bounded(m.odd, half, 0), Bounded(m.even, -half, 0)}) {
      ASSERT_EQ(exact_rounding(v, 0), m.even) << show(v, 0);
      double out = 0;
      if (detail::decide(v, 0, out)) {
        EXPECT_EQ(out, m.even) << show(v, 0);
      }
      for (double err : {std::ldexp(std::fabs(half), -60), std::fabs(half) / 2}) {
        const Bounded around(v.hi, v.lo, err);
        EXPECT_FALSE(decided(around)) << show(around, 0);
      }
    }
  }
}

TEST(OracleRounding, ZeroIsDecidedOnlyWhenKnownExactlyAndIsPlusZero) {
  EXPECT_TRUE(test::same_double(decision(Bounded(0.0)), 0.0));
  EXPECT_TRUE(test::same_double(decision(Bounded(-0.0)), 0.0));  // an exact zero is +0, as the exact stage gives it
  EXPECT_TRUE(test::same_double(decision(Bounded(0.0), -500), 0.0));
  // Intervals that straddle zero, or touch it, hold reals of both signs (or zero and a nonzero double).
  for (const Bounded& v : {Bounded(0.0, 0.0, 0x1p-1074), Bounded(0.0, 0.0, 1.0), Bounded(0x1p-800, 0.0, 0x1p-799),
                           Bounded(-0x1p-800, 0.0, 0x1p-799), Bounded(1.0, 0.0, 1.0), Bounded(-1.0, 0.0, 2.0),
                           Bounded(0x1p-800, -0x1p-853, 0x1p-800)}) {
    EXPECT_FALSE(decided(v)) << show(v, 0);
    EXPECT_TRUE(sound(v, 0));
  }
}

TEST(OracleRounding, NearUnderflowNoResultBelowTheNormalRangeIsDecided) {
  // Scaled back to 2^-1022 and below, rounding no longer commutes with the scaling: below 2^-1022 the gap is the
  // constant 2^-1074 (2^-1022 itself has the same gap on both sides), and subnormal results lose bits. decide
  // leaves every result below 2^-1021 and every unscaled value below 2^-900 (fast_path.hpp); around those edges
  // its verdicts are sound.
  for (int scale : {-1019, -1020, -1021, -1022, -1023, -1024, -1040, -1073, -1074, -1075, -1080})
    for (double d : anchors({-1, 0, 1}))
      for (const Bounded& v : intervals_around(d)) ASSERT_TRUE(sound(v, scale));
  for (double d : anchors({-902, -901, -900, -899}))
    for (const Bounded& v : intervals_around(d)) ASSERT_TRUE(sound(v, 0));
  // Exactly representable subnormal and boundary results, known exactly: left to the exact stage.
  EXPECT_FALSE(decided(Bounded(1.0), -1022));                 // 2^-1022, the smallest normal
  EXPECT_FALSE(decided(Bounded(1.5), -1030));                 // a subnormal
  EXPECT_FALSE(decided(Bounded(0x1p-1074)));                  // the smallest subnormal, unscaled
  EXPECT_EQ(decision(Bounded(1.5), -1021), 1.5 * 0x1p-1021);  // the first binade decided
}

TEST(OracleRounding, NearOverflowNothingThatMayRoundToInfinityIsDecided) {
  // Near DBL_MAX the reals from DBL_MAX + 2^970 on round to infinity (an error for the oracle, never a decision).
  // decide leaves every result from 2^1022 on; around that edge its verdicts are sound.
  for (int scale : {1019, 1020, 1021, 1022, 1023, 1024})
    for (double d : anchors({-1, 0, 1}))
      for (const Bounded& v : intervals_around(d)) ASSERT_TRUE(sound(v, scale));
  for (double d : anchors({899, 900, 901, 1023}))
    for (const Bounded& v : intervals_around(d)) ASSERT_TRUE(sound(v, 0));
  const double largest = std::numeric_limits<double>::max();
  EXPECT_FALSE(decided(Bounded(largest)));
  EXPECT_FALSE(decided(Bounded(largest / 2, 0x1p969, 0x1p969), 1));
  EXPECT_FALSE(decided(Bounded(1.0), 1023));
}

TEST(OracleRounding, NonFiniteIsNeverDecided) {
  for (double bad : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
    EXPECT_FALSE(decided(Bounded(bad, 0.0, 0.0)));
    EXPECT_FALSE(decided(Bounded(1.0, bad, 0.0)));
    EXPECT_FALSE(decided(Bounded(1.0, 0.0, bad)));
  }
}

// Every anchor at exponents across decide's range and its edges, unscaled and scaled as the gradient (2^-E) and
// the Hessian (2^-2E) are.
struct Sweep {
  std::vector<std::pair<double, int>> cases;  // (anchor, scale)
  Sweep() {
    for (double d : anchors({-900, -899, -500, -54, -53, -1, 0, 1, 52, 53, 54, 500, 899, 900})) cases.push_back({d, 0});
    for (int scale : {-1000, -121, -120, -1, 1, 120, 1000})
      for (double d : anchors({-1, 0, 1, 20})) cases.push_back({d, scale});
  }
};

TEST(OracleRounding, DecidesOnlyIntervalsThatRoundToOneDouble) {
  // Soundness, over about a million intervals (a fifth of them decided) at the edges of the rounding intervals of
  // powers of two and their neighbours, of both signs and scaled: every decision is the rounding of every real of its
  // interval.
  int intervals = 0, decisions = 0, failures = 0;
  for (const auto& [d, scale] : Sweep().cases)
    for (const Bounded& v : intervals_around(d)) {
      ++intervals;
      const ::testing::AssertionResult ok = sound(v, scale);
      decisions += decided(v, scale);
      if (!ok && ++failures <= 10) ADD_FAILURE() << ok.message();
    }
  std::printf("%d intervals, %d decided\n", intervals, decisions);
  EXPECT_EQ(failures, 0);
  EXPECT_GT(decisions, 10000);  // the sweep does reach decisions (not only intervals decide leaves)
}

TEST(OracleRounding, DecidesEveryIntervalWellInsideARoundingIntervalInItsRange) {
  // Completeness within the contract (fast_path.hpp): an interval within the smaller half-gap of hi, short of it by
  // 2^-20 of it (decide keeps 2^-49 for its own rounding), with |hi| in [2^-900, 2^901) and |hi 2^scale| in
  // [2^-1021, 2^1022), is decided, as hi 2^scale. A decision that took the gap below on both sides everywhere (too
  // cautious, not wrong) would leave many of these.
  int checked = 0, failures = 0;
  for (const auto& [d, scale] : Sweep().cases) {
    const int e = std::ilogb(d);
    if (e < -900 || e > 900 || e + scale < -1021 || e + scale > 1021) continue;
    const double smaller_half_gap = std::ldexp(1.0, power_of_two(d) ? e - 54 : e - 53);
    for (const Bounded& v : intervals_around(d)) {
      if (std::fabs(v.lo) + v.err > smaller_half_gap * (1 - 0x1p-20)) continue;
      ++checked;
      const double expected = std::ldexp(d, scale);
      if (!test::same_double(decision(v, scale), expected) && ++failures <= 10)
        ADD_FAILURE() << show(v, scale) << ": not decided as " << std::hexfloat << expected;
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GT(checked, 10000);
}

// --- End to end: one hinge -----------------------------------------------------------------------------------

// Hinge edge x1 = 0, x2 = (1, 0, 0); x0 = (a, s, 0) (the upper triangle in z = 0, height 1); x3 = (c, -s, s)
// (the lower one tilted by 45 degrees). By eq. (4) in the exact form (oracle/README.md), grad_x1 =
// -(d1 N / nn + d~1 Nt / tt) / l0 with l0 = 1, d1 = a - 1, N = (0, 0, s), d~1 = c - 1, Nt = s (0, 1, 1): its z
// component is s ((1 - a) + (1 - c) / 2), exactly. With c = -1 + 2^-52 that is s (2 - 2^-53 - a): for a = 0 the
// midpoint below 2 (a tie, to the even 2), for a tiny a > 0 just below it (rounding to 2 - 2^-52). s = -1 turns
// the hinge by pi about its edge, negating it.
X12 hinge_near_two(double a, double c, double s) { return {a, s, 0, 0, 0, 0, 1, 0, 0, c, -s, s}; }

TEST(OracleRounding, HingeOutputJustBelowAPowerOfTwoIsTheEnclosuresDouble) {
  // grad_x1.z = s (2 - 2^-53 - a), a = 2^-110 ... 2^-1000: below the midpoint under 2 by less than a double-double
  // holds next to 2 (its low part, about 2^-53, keeps nothing below 2^-106), so the fast path's approximation is
  // that midpoint: hi = 2 (ties to even), lo = -2^-53, a bound err > 0 around it. The exact value rounds to
  // 2 - 2^-52 (checked in MPFR and by the enclosures). Asserted: the fast path gives the enclosures' doubles, bit
  // for bit, every output; a decision with the gap above 2 on both sides would have given 2.
  const double c = -1 + 0x1p-52;
  int sharp = 0;
  for (double a : {0x1p-110, 0x1p-120, 0x1p-300, 0x1p-1000})
    for (double s : {1.0, -1.0}) {
      const X12 x = hinge_near_two(a, c, s);
      const std::string what = "a = " + std::to_string(std::ilogb(a)) + (s > 0 ? "" : ", mirrored");
      Real exact(2200);  // s (2 - 2^-53 - a), exactly
      mpfr_set_d(exact.v, 2, MPFR_RNDN);
      mpfr_sub_d(exact.v, exact.v, 0x1p-53, MPFR_RNDN);
      mpfr_sub_d(exact.v, exact.v, a, MPFR_RNDN);
      mpfr_mul_d(exact.v, exact.v, s, MPFR_RNDN);
      ASSERT_EQ(nearest(exact), s * (2 - 0x1p-52)) << what;
      const CertifiedTheta enclosures = certified_theta_derivatives(x, without_fast_path());
      ASSERT_EQ(enclosures.grad[3 + 2], s * (2 - 0x1p-52)) << what << ": the construction's premise";
      const CertifiedTheta fast = certified_theta_derivatives(x);
      EXPECT_EQ("", test::first_difference(fast, enclosures)) << what;
      EXPECT_EQ(fast.grad[3 + 2], s * (2 - 0x1p-52))
          << what << std::hexfloat << ": the fast path gave " << fast.grad[3 + 2];
      // The premise that makes the case sharp, in the fast path's own arithmetic: its approximation is the power of
      // two and its interval lies within the half-gap above 2 (2^-52), which a decision taking that half-gap on both
      // sides would accept.
      const std::optional<detail::BoundedHinge> b = detail::bounded_hinge(x, true);
      ASSERT_TRUE(b) << what;
      const Bounded& g = b->grad[3 + 2];
      sharp += g.hi == s * 2 && std::fabs(g.lo) + g.err < 0x1p-52;
    }
  EXPECT_EQ(sharp, 8) << "the fast path's approximation of grad_x1.z is no longer 2 on every hinge here: the test "
                         "no longer checks the gap below a power of two (choose a smaller a)";
}

TEST(OracleRounding, HingeOutputsOnTheMidpointsBesideAPowerOfTwoRoundToEvenAsTheEnclosuresDo) {
  // grad_x1.z = s (1 - a + (1 - c) / 2) exactly (hinge_near_two): the midpoint below 2 (c = -1 + 2^-52, a = 0)
  // and the one above it (c = -1 - 2^-51, a = 0) are ties, both to the even 2; just above the upper one (a < 0
  // tiny) rounds up to 2 + 2^-51. The fast path gives the enclosures' doubles on all.
  struct Case {
    double a, c, expected;
  };
  for (const Case& k : {Case{0, -1 + 0x1p-52, 2}, Case{0, -1 - 0x1p-51, 2}, Case{-0x1p-110, -1 - 0x1p-51, 2 + 0x1p-51},
                        Case{0x1p-110, -1 - 0x1p-51, 2}})
    for (double s : {1.0, -1.0}) {
      const X12 x = hinge_near_two(k.a, k.c, s);
      std::ostringstream what;
      what << std::hexfloat << "a " << k.a << ", c " << k.c << ", s " << s;
      const CertifiedTheta enclosures = certified_theta_derivatives(x, without_fast_path());
      ASSERT_EQ(enclosures.grad[3 + 2], s * k.expected) << what.str();
      EXPECT_EQ("", test::first_difference(certified_theta_derivatives(x), enclosures)) << what.str();
    }
}

// --- End to end: a mesh ----------------------------------------------------------------------------------------

TEST(OracleRounding, MeshGradientJustBelowAPowerOfTwoIsTheEnclosuresDouble) {
  // One hinge, tan energy (eq. (8)): rest flat, x0 = (a0, 1, 0), x1 = 0, x2 = (1, 0, 0), x3 = (1/2, -4, 0), so
  // Algorithm 1's a = 6 |e0|^2 / (|N| + |Nt|) = 6 / 5; deformed with x3 = (1/2, 0, 4 s): theta = -s pi/2 (t = -s),
  // psi' = 2 a k (2 t) (1 + t^2) = -s 48 k / 5, and grad_x1.z = 1 - a0 (the lower triangle is vertical). So the
  // mesh gradient at x1.z is -s (48 k / 5)(1 - a0). k (near 5/6) and a0 (near 2^-52) were chosen, by exact
  // rationals, to put it 2^-105.6 below the midpoint 8 - 2^-51 under 8 (checked in MPFR below): less than a
  // double-double holds next to 8 (its low part, about 2^-51, keeps nothing below 2^-104), so the fast path's sum
  // lands on that midpoint, hi = 8. It rounds to 8 - 2^-50. Asserted: the mesh fast path gives the enclosures'
  // doubles, bit for bit, every output (a decision with the gap above 8 on both sides gave -s 8: the commit message
  // of this test records the mutation run).
  const double k = 0x1.aaaaaaaaaaaacp-1, a0 = 0x1.0ccccccccccccp-52;
  Real exact, midpoint;  // (48 k / 5)(1 - a0) within 2^-255 relative (only / 5 rounds); 8 - 2^-51 exactly
  mpfr_set_d(exact.v, 1, MPFR_RNDN);
  mpfr_sub_d(exact.v, exact.v, a0, MPFR_RNDN);
  mpfr_mul_d(exact.v, exact.v, k, MPFR_RNDN);
  mpfr_mul_ui(exact.v, exact.v, 48, MPFR_RNDN);
  mpfr_div_ui(exact.v, exact.v, 5, MPFR_RNDN);
  mpfr_set_d(midpoint.v, 8, MPFR_RNDN);
  mpfr_sub_d(midpoint.v, midpoint.v, 0x1p-51, MPFR_RNDN);
  Real below;
  mpfr_sub(below.v, midpoint.v, exact.v, MPFR_RNDN);
  ASSERT_GT(mpfr_sgn(below.v), 0);
  ASSERT_LT(mpfr_cmp_d(below.v, 0x1p-105), 0);  // below the midpoint by less than 2^-105 (the premise)
  ASSERT_EQ(nearest(exact), 8 - 0x1p-50);
  for (double s : {1.0, -1.0}) {
    Mesh deformed;
    deformed.vertices = {{a0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0.5, 0, 4 * s}};
    deformed.faces = {{0, 1, 2}, {3, 2, 1}};
    Mesh rest = deformed;
    rest.vertices[3] = {0.5, -4, 0};
    const Topology t = build_topology(deformed);
    EnergyParameters p;
    p.model = Model::tan;
    p.k = k;
    const CertifiedMesh enclosures = certified_mesh(deformed, rest, t, p, want_all, without_fast_path());
    ASSERT_EQ(enclosures.rounded.gradient.at(3 * 1 + 2), -s * (8 - 0x1p-50)) << "the construction's premise";
    const CertifiedMesh fast = certified_mesh(deformed, rest, t, p);
    EXPECT_EQ("", test::first_difference(fast, enclosures))
        << "s = " << s << std::hexfloat << ": the fast path gave " << fast.rounded.gradient.at(3 * 1 + 2);
  }
}

}  // namespace
}  // namespace hinge::oracle
