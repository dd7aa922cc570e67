// The fast path's arithmetic (oracle/src/bounded.hpp): every operation's error bound holds against the
// exact result (MPFR at 3000 bits, which holds every operand and result below exactly or within
// 2^-2900), for exact and inexact operands, across cancellation, near underflow and at exact zeros; and
// the bounds are tight enough to decide a rounding (a few units of 2^-106 on well-scaled operands).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>
#include <random>

#include "src/bounded.hpp"

namespace hinge::oracle::detail {
namespace {

constexpr mpfr_prec_t kBits = 3000;

struct Exact {
  mpfr_t v;
  Exact() { mpfr_init2(v, kBits); }
  ~Exact() { mpfr_clear(v); }
  Exact(const Exact&) = delete;
  Exact& operator=(const Exact&) = delete;
};

// A Bounded operand and the exact real it stands for: hi + lo + delta, |delta| <= err.
struct Operand {
  Bounded b;
  double delta = 0;
};

void set(Exact& x, const Operand& a) {
  mpfr_set_d(x.v, a.b.hi, MPFR_RNDN);
  mpfr_add_d(x.v, x.v, a.b.lo, MPFR_RNDN);
  mpfr_add_d(x.v, x.v, a.delta, MPFR_RNDN);  // exact at 3000 bits for the exponents drawn here
}

// |r.hi + r.lo - exact| <= r.err, decided in MPFR.
::testing::AssertionResult holds(const Bounded& r, const Exact& exact) {
  Exact d;
  mpfr_set_d(d.v, r.hi, MPFR_RNDN);
  mpfr_add_d(d.v, d.v, r.lo, MPFR_RNDN);
  mpfr_sub(d.v, d.v, exact.v, MPFR_RNDN);
  mpfr_abs(d.v, d.v, MPFR_RNDN);
  if (mpfr_cmp_d(d.v, r.err) <= 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "error " << mpfr_get_d(d.v, MPFR_RNDU) << " above the bound " << r.err
                                       << " (hi " << r.hi << ", lo " << r.lo << ")";
}

// A normalized double-double of magnitude 2^e (e in [lo_e, hi_e]), sometimes a plain double or zero, with
// an input error of relative size 2^-100 or none.
struct Draw {
  std::mt19937_64 rng{20261204};
  int lo_e = -30, hi_e = 30;
  Operand operator()() {
    std::uniform_real_distribution<double> unit(1, 2);
    std::uniform_int_distribution<int> exponent(lo_e, hi_e), kind(0, 5);
    Operand a;
    const int k = kind(rng);
    if (k == 0) return a;  // an exact zero
    const double hi = std::ldexp(unit(rng), exponent(rng)) * (rng() & 1 ? -1 : 1);
    const double lo = k == 1 ? 0.0 : std::ldexp(unit(rng) - 1.5, std::ilogb(hi) - 54);
    const double s = hi + lo;  // renormalize: hi = RN(hi + lo)
    a.b = Bounded(s, (hi - s) + lo, 0);
    if (k >= 4) {
      a.b.err = std::ldexp(std::fabs(s), -100);
      a.delta = a.b.err * (std::uniform_real_distribution<double>(-1, 1)(rng));
    }
    return a;
  }
};

enum class Op { add, sub, mul, reciprocal, root };

void check(Op op, Draw& draw, int count) {
  Exact x, y, z;
  for (int i = 0; i < count; ++i) {
    Operand a = draw(), b = draw();
    set(x, a);
    set(y, b);
    Bounded r;
    switch (op) {
      case Op::add:
        r = a.b + b.b;
        mpfr_add(z.v, x.v, y.v, MPFR_RNDN);
        break;
      case Op::sub:
        // Cancellation: b close to a in half the draws.
        if (i % 2 == 0) {
          b = a;
          b.b.lo = b.b.lo + std::ldexp(b.b.hi, -80);
          b.b = b.b + Bounded(0.0);
          set(y, b);
        }
        r = a.b - b.b;
        mpfr_sub(z.v, x.v, y.v, MPFR_RNDN);
        break;
      case Op::mul:
        r = a.b * b.b;
        mpfr_mul(z.v, x.v, y.v, MPFR_RNDN);
        break;
      case Op::reciprocal:
        if (!(bounded::lower(a.b) > 0)) continue;
        r = reciprocal(a.b);
        mpfr_ui_div(z.v, 1, x.v, MPFR_RNDN);  // within 2^-3000 relative: far below any bound here
        break;
      case Op::root:
        a.b = Bounded(std::fabs(a.b.hi), std::fabs(a.b.hi) == a.b.hi ? a.b.lo : -a.b.lo, a.b.err);
        a.delta = std::fabs(a.delta);
        if (!(bounded::lower(a.b) > 0)) continue;
        set(x, a);
        r = root(a.b);
        mpfr_sqrt(z.v, x.v, MPFR_RNDN);
        break;
    }
    ASSERT_TRUE(holds(r, z)) << "operation " << static_cast<int>(op) << ", draw " << i;
  }
}

TEST(Bounded, EveryOperationsBoundHoldsOnWellScaledOperands) {
  Draw draw;
  for (Op op : {Op::add, Op::sub, Op::mul, Op::reciprocal, Op::root}) check(op, draw, 20000);
}

TEST(Bounded, EveryOperationsBoundHoldsNearUnderflow) {
  Draw draw;
  draw.lo_e = -1070;  // products and their low parts underflow; eta = 2^-1000 must cover what is lost
  draw.hi_e = -480;
  for (Op op : {Op::add, Op::sub, Op::mul, Op::reciprocal, Op::root}) check(op, draw, 20000);
}

TEST(Bounded, ExactZeroFactorsAndProductsOfDoublesStayExact) {
  const Bounded zero(0.0), x(0.1, 1e-18, 1e-30), p(3.0), q(0.1);
  EXPECT_EQ((zero * x).err, 0.0);
  EXPECT_EQ((x * zero).err, 0.0);
  EXPECT_EQ((p * q).err, 0.0);  // 3 * 0.1 is a two_prod: exact
  EXPECT_EQ((zero + zero).err, 0.0);
  const Bounded pq = p * q;
  EXPECT_EQ(pq.hi, 3.0 * 0.1);
  EXPECT_EQ(pq.lo, std::fma(3.0, 0.1, -(3.0 * 0.1)));
}

TEST(Bounded, BoundsOnWellScaledOperandsAreAFewUnitsOf2ToTheMinus106) {
  // What lets the fast path decide: from exact operands near 1 a product, sum, reciprocal and square root
  // carry bounds below 2^-100 of the result (the analysis gives at most 7 u^2 for a product).
  const Bounded a(1.2345678901234567, 3.1e-17, 0), b(0.7654321098765432, -2.7e-17, 0);
  for (const Bounded& r : {a * b, a + b, reciprocal(a), root(b)}) EXPECT_LT(r.err, std::ldexp(std::fabs(r.hi), -100));
}

}  // namespace
}  // namespace hinge::oracle::detail
