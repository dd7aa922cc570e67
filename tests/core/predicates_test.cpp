// Unit tests of the exact predicates zero_area_exact and hinge_orientation_exact
// (core/src/predicates.cpp): cases the floating-point filter decides, cases only exact arithmetic
// decides, and exponents from subnormal to near overflow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "hinge/core/predicates.hpp"

namespace hinge {
namespace {

constexpr double kDenormMin = std::numeric_limits<double>::denorm_min();
constexpr double kMax = std::numeric_limits<double>::max();

Point add(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point scale(double s, const Point& a) { return {s * a[0], s * a[1], s * a[2]}; }

// The naive double evaluation of the area vector (b - a) x (c - a), for showing that it errs.
Point cross_from_differences(const Point& a, const Point& b, const Point& c) {
  const Point e{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, f{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
}

// The area vector summed as a x b + b x c + c x a: what a translation-sensitive code computes.
Point cross_from_origin(const Point& a, const Point& b, const Point& c) {
  auto cross = [](const Point& p, const Point& q) {
    return Point{p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
  };
  return add(add(cross(a, b), cross(b, c)), cross(c, a));
}

bool is_zero(const Point& v) { return v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0; }

// The naive double evaluation of det[e0, x0 - x1, x1 - x3].
double naive_orientation(const Point& x0, const Point& x1, const Point& x2, const Point& x3) {
  const Point e{x2[0] - x1[0], x2[1] - x1[1], x2[2] - x1[2]};
  const Point u{x0[0] - x1[0], x0[1] - x1[1], x0[2] - x1[2]};
  const Point w{x1[0] - x3[0], x1[1] - x3[1], x1[2] - x3[2]};
  return e[0] * (u[1] * w[2] - u[2] * w[1]) + e[1] * (u[2] * w[0] - u[0] * w[2]) + e[2] * (u[0] * w[1] - u[1] * w[0]);
}

int sign(std::int64_t v) { return (v > 0) - (v < 0); }

TEST(Predicates, ZeroAreaExactOnCollinearPointsFarFromOrigin) {
  // a ~ 1e15 and direction d with up to 48 significant bits, all in units of 1/4: a + s d stays below 2^51,
  // so a, a + s d, a + t d are exact doubles and exactly collinear. The ratio t / s is not a power of two.
  std::mt19937_64 rng(2013);
  std::uniform_int_distribution<std::int64_t> base(2'000'000'000'000'000, 4'000'000'000'000'000);  // quarters
  std::uniform_int_distribution<std::int64_t> dir(-(std::int64_t(1) << 48), std::int64_t(1) << 48);
  int naive_wrong = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    Point a, d;
    for (int k = 0; k < 3; ++k) {
      a[k] = double(base(rng)) * 0.25 * (k == 1 ? -1.0 : 1.0);
      d[k] = double(dir(rng)) * 0.25;
    }
    const Point b = add(a, scale(3.0, d)), c = add(a, scale(-5.0, d));
    for (int k = 0; k < 3; ++k) {  // the construction is exact
      ASSERT_EQ(b[k] - a[k], 3.0 * d[k]);
      ASSERT_EQ(c[k] - a[k], -5.0 * d[k]);
    }
    EXPECT_TRUE(zero_area_exact(a, b, c));
    EXPECT_TRUE(zero_area_exact(c, a, b));
    if (!is_zero(cross_from_origin(a, b, c))) ++naive_wrong;
    // Moving c by one unit in the last place of one coordinate leaves the line.
    Point c1 = c;
    c1[trial % 3] = std::nextafter(c1[trial % 3], kMax);
    if (d[(trial + 1) % 3] != 0.0 || d[(trial + 2) % 3] != 0.0) {
      EXPECT_FALSE(zero_area_exact(a, b, c1));
    }
  }
  // The translation-sensitive double formula is wrong on most of these cases; the exact predicate is not.
  EXPECT_GT(naive_wrong, 1000);
}

TEST(Predicates, ZeroAreaFilterFailsButExactAnswerIsNonzero) {
  // a = (2^-80, 0, 0), b = (1, 1, 0), c = (2, 2, 0): in double b - a and c - a round to (1, 1, 0) and
  // (2, 2, 0), collinear, but exactly (b - a) x (c - a) = (0, 0, -2^-80).
  const double delta = 0x1p-80;
  const Point a{delta, 0, 0}, b{1, 1, 0}, c{2, 2, 0};
  ASSERT_TRUE(is_zero(cross_from_differences(a, b, c)));
  EXPECT_FALSE(zero_area_exact(a, b, c));
  EXPECT_TRUE(zero_area_exact({0, 0, 0}, b, c));
  // The same in every coordinate plane.
  EXPECT_FALSE(zero_area_exact({0, delta, 0}, {0, 1, 1}, {0, 2, 2}));
  EXPECT_FALSE(zero_area_exact({0, 0, delta}, {1, 0, 1}, {2, 0, 2}));
}

TEST(Predicates, ZeroAreaAtTinyExponentsAndSubnormals) {
  const Point o{0, 0, 0};
  EXPECT_TRUE(zero_area_exact(o, {kDenormMin, 0, 0}, {2 * kDenormMin, 0, 0}));
  EXPECT_TRUE(
      zero_area_exact(o, {kDenormMin, kDenormMin, kDenormMin}, {-3 * kDenormMin, -3 * kDenormMin, -3 * kDenormMin}));
  EXPECT_FALSE(zero_area_exact(o, {kDenormMin, 0, 0}, {0, kDenormMin, 0}));
  EXPECT_FALSE(zero_area_exact(o, {kDenormMin, 0, 0}, {0, 0, kDenormMin}));
  // Products of subnormal differences underflow to zero in double; the exact answer is still "nonzero".
  const Point s{3 * kDenormMin, 5 * kDenormMin, 0}, t{5 * kDenormMin, 3 * kDenormMin, 0};
  ASSERT_TRUE(is_zero(cross_from_differences(o, s, t)));
  EXPECT_FALSE(zero_area_exact(o, s, t));
  // At the 1e-300 scale: collinear and nearly collinear.
  const Point p{1e-300, 2e-300, 3e-300};
  EXPECT_TRUE(zero_area_exact(p, scale(2.0, p), scale(-0.5, p)));
  Point q = scale(2.0, p);
  q[2] = std::nextafter(q[2], 0.0);
  EXPECT_FALSE(zero_area_exact(p, q, scale(-0.5, p)));
}

TEST(Predicates, ZeroAreaNearOverflowWhereDifferencesOverflow) {
  // b - a overflows to infinity in double; the exact decision is unaffected.
  const double m = kMax;
  EXPECT_TRUE(zero_area_exact({-m, -m, 0}, {0, 0, 0}, {m, m, 0}));
  EXPECT_FALSE(zero_area_exact({-m, -m, 0}, {0, 0, 0}, {m, std::nextafter(m, 0.0), 0}));
  EXPECT_TRUE(zero_area_exact({m, -m, m}, {m, -m, m}, {0, 1, 2}));  // two coincident points
}

TEST(Predicates, ZeroAreaCoincidentPoints) {
  const Point a{0.1, 0.2, 0.3}, b{0.7, -1.1, 2.5};
  EXPECT_TRUE(zero_area_exact(a, a, b));
  EXPECT_TRUE(zero_area_exact(a, b, a));
  EXPECT_TRUE(zero_area_exact(b, a, a));
  EXPECT_TRUE(zero_area_exact(a, a, a));
}

// Random small-integer configurations, scaled by 2^e (e from the subnormal range to near overflow) and
// translated by a multiple of 2^e: every coordinate stays an exact double, collinearity and the
// orientation sign are unchanged, and the expected answers come from exact integer arithmetic.
TEST(Predicates, AgreeWithIntegerArithmeticAcrossAllExponents) {
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<int> small(-3, 3), exponent(-1074, 1023 - 50);
  std::uniform_int_distribution<std::int64_t> shift(-(std::int64_t(1) << 45), std::int64_t(1) << 45);
  int collinear = 0, flat = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::int64_t v[4][3];
    for (auto& p : v) {
      for (auto& c : p) c = small(rng);
    }
    const int e = exponent(rng);
    std::int64_t t[3] = {0, 0, 0};
    if (trial % 2 == 1) {
      for (auto& c : t) c = shift(rng);
    }
    Point x[4];
    for (int i = 0; i < 4; ++i) {
      for (int k = 0; k < 3; ++k) x[i][k] = std::ldexp(double(v[i][k] + t[k]), e);  // exact
    }
    // Area vector of (v0, v1, v2).
    std::int64_t d1[3], d2[3];
    for (int k = 0; k < 3; ++k) {
      d1[k] = v[1][k] - v[0][k];
      d2[k] = v[2][k] - v[0][k];
    }
    const bool zero =
        d1[1] * d2[2] == d1[2] * d2[1] && d1[2] * d2[0] == d1[0] * d2[2] && d1[0] * d2[1] == d1[1] * d2[0];
    collinear += zero;
    ASSERT_EQ(zero_area_exact(x[0], x[1], x[2]), zero) << "trial " << trial << ", e = " << e;
    // det[x2 - x1, x0 - x1, x1 - x3] with (x0, x1, x2, x3) = (v0, v1, v2, v3).
    std::int64_t e0[3], u[3], w[3];
    for (int k = 0; k < 3; ++k) {
      e0[k] = v[2][k] - v[1][k];
      u[k] = v[0][k] - v[1][k];
      w[k] = v[1][k] - v[3][k];
    }
    const std::int64_t det =
        e0[0] * (u[1] * w[2] - u[2] * w[1]) + e0[1] * (u[2] * w[0] - u[0] * w[2]) + e0[2] * (u[0] * w[1] - u[1] * w[0]);
    flat += det == 0;
    ASSERT_EQ(hinge_orientation_exact(x[0], x[1], x[2], x[3]), sign(det)) << "trial " << trial << ", e = " << e;
  }
  // Both outcomes occur often enough for the comparison to mean something.
  EXPECT_GT(collinear, 100);
  EXPECT_GT(flat, 500);
}

TEST(Predicates, HingeOrientationMatchesConventionsCheckHinge) {
  // docs/contract.md: x1 = (0,0,0), x2 = (1,0,0), x0 = (0.5,1,0), x3 = (0.5,-1,0): flat, theta = 0, n = +z.
  // Lifting x0 along +n makes theta negative; the predicate has the sign of theta.
  const Point x1{0, 0, 0}, x2{1, 0, 0}, x0{0.5, 1, 0}, x3{0.5, -1, 0};
  EXPECT_EQ(hinge_orientation_exact(x0, x1, x2, x3), 0);
  for (const double h : {1.0, 1e-5, 1e-200, kDenormMin}) {
    EXPECT_EQ(hinge_orientation_exact({0.5, 1, h}, x1, x2, x3), -1) << h;   // x0 up: valley, theta < 0
    EXPECT_EQ(hinge_orientation_exact({0.5, 1, -h}, x1, x2, x3), 1) << h;   // x0 down: ridge, theta > 0
    EXPECT_EQ(hinge_orientation_exact(x0, x1, x2, {0.5, -1, h}), -1) << h;  // x3 up: valley
    EXPECT_EQ(hinge_orientation_exact(x0, x1, x2, {0.5, -1, -h}), 1) << h;
  }
  // det[e0, x0 - x1, x1 - x3] for x0 = (0.5, 1, h): e0 = (1,0,0), so det = 1 * (1 * 0 - h * 1) = -h.
  EXPECT_EQ(naive_orientation({0.5, 1, 2.0}, x1, x2, x3), -2.0);
  // Folded flat onto itself (x3 on the x0 side) and a zero-length hinge edge: orientation 0.
  EXPECT_EQ(hinge_orientation_exact(x0, x1, x2, x0), 0);
  EXPECT_EQ(hinge_orientation_exact(x0, x1, x1, x3), 0);
  // The same hinge labelled from its other face, (x3, x2, x1, x0), has the same sign: theta belongs to the
  // hinge, not to the labelling.
  EXPECT_EQ(hinge_orientation_exact({0.5, -1, 0.5}, x2, x1, {0.5, 1, 0}), -1);  // x3 up, relabelled
  EXPECT_EQ(hinge_orientation_exact({0.5, -1, 0}, x2, x1, {0.5, 1, 0.5}), -1);  // x0 up, relabelled
  EXPECT_EQ(hinge_orientation_exact({0.5, -1, 0}, x2, x1, {0.5, 1, -0.5}), 1);
}

TEST(Predicates, HingeOrientationFilterFailsButExactAnswerIsNonzero) {
  // x0, x2, x3 and (0, 0, 0) lie in the plane z = x; x1 = (delta, 0, 0) is just off it. Every difference
  // from x1 rounds delta away, so the double determinant is exactly 0, while exactly
  // det[e0, x0 - x1, x1 - x3] = -delta (worked out by hand: u x w = (-1, 0, 1 - 2 delta), e0 . (u x w) =
  // -(1 - delta) + 1 - 2 delta).
  const double delta = 0x1p-80;
  const Point x0{0.5, 1, 0.5}, x2{1, 0, 1}, x3{0.5, -1, 0.5};
  ASSERT_EQ(naive_orientation(x0, {delta, 0, 0}, x2, x3), 0.0);
  EXPECT_EQ(hinge_orientation_exact(x0, {delta, 0, 0}, x2, x3), -1);
  EXPECT_EQ(hinge_orientation_exact(x0, {-delta, 0, 0}, x2, x3), 1);
  EXPECT_EQ(hinge_orientation_exact(x0, {0, 0, 0}, x2, x3), 0);
  // The same hinge far from the origin: translating by an exact offset keeps the sign.
  const Point offset{0x1p40, -0x1p41, 0x1p39};
  EXPECT_EQ(hinge_orientation_exact(add(x0, offset), add(Point{0, 0, 0}, offset), add(x2, offset), add(x3, offset)), 0);
}

TEST(Predicates, HingeOrientationNearOverflow) {
  const double m = kMax / 2;
  // The check hinge scaled up so that differences overflow: signs as at unit scale.
  const Point x1{-m, 0, 0}, x2{m, 0, 0}, x0{0, m, 0}, x3{0, -m, 0};
  EXPECT_EQ(hinge_orientation_exact(x0, x1, x2, x3), 0);
  EXPECT_EQ(hinge_orientation_exact({0, m, kDenormMin}, x1, x2, x3), -1);
  EXPECT_EQ(hinge_orientation_exact({0, m, -kMax}, x1, x2, x3), 1);
}

}  // namespace
}  // namespace hinge
