// The sign filter's guard (hinge/fast/exact.hpp): tame coordinates give differences inside it, so the
// filter without the guard's test decides as the guarded one; and the classification of coordinates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "fast_support.hpp"
#include "hinge/fast/exact.hpp"

namespace hinge::fast {
namespace {

constexpr double kLo = 0x1p-300, kHi = 0x1p300;  // orientation_filter's guard
bool in_guard(double d) { return d == 0.0 || (std::fabs(d) >= kLo && std::fabs(d) <= kHi); }

// The smallest and largest positive tame doubles, found from tame_coordinate itself (so that a change of
// its range is tested, not the range this file expects).
double smallest_tame() {
  double x = 1.0;
  while (tame_coordinate(x / 2) && x / 2 > 0) x /= 2;
  while (tame_coordinate(std::nextafter(x, 0.0)) && std::nextafter(x, 0.0) > 0) x = std::nextafter(x, 0.0);
  return x;
}
double largest_tame() {
  double x = 1.0;
  while (tame_coordinate(x * 2) && std::isfinite(x * 2)) x *= 2;
  while (tame_coordinate(std::nextafter(x, 1e308)) && std::isfinite(std::nextafter(x, 1e308))) x = std::nextafter(x, 1e308);
  return x;
}

// Tame values of every kind: the ends of the range and their neighbours inside it, zeros, random
// magnitudes across the range, and pairs one unit in the last place apart.
std::vector<double> tame_samples(unsigned seed) {
  const double lo = smallest_tame(), hi = largest_tame();
  std::vector<double> v{0.0, -0.0, lo, -lo, std::nextafter(lo, 1.0), hi, -hi, std::nextafter(hi, 0.0), 1.0, -1.0};
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> exponent(std::ilogb(lo), std::ilogb(hi));
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  for (int i = 0; i < test::cases(2000); ++i) {
    const double x = std::clamp(std::ldexp(mantissa(rng), exponent(rng)), lo, hi) * (i % 2 ? -1 : 1);
    v.push_back(x);
    v.push_back(tame_coordinate(std::nextafter(x, 0.0)) ? std::nextafter(x, 0.0) : x);
  }
  return v;
}

TEST(Exact, TameCoordinatesGiveDifferencesInsideTheFilterGuard) {
  EXPECT_EQ(smallest_tame(), 0x1p-200);
  EXPECT_EQ(largest_tame(), 0x1p299);
  const std::vector<double> v = tame_samples(1);
  for (double x : v) ASSERT_TRUE(tame_coordinate(x)) << x;
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<std::size_t> pick(0, v.size() - 1);
  // Every pair among the special values and neighbours, and random pairs.
  for (std::size_t i = 0; i < 2 * v.size(); ++i)
    for (std::size_t j : {i / 2, pick(rng), (i / 2 + 1) % v.size()}) {
      const double x = v[i / 2], y = v[j], d = x - y;
      EXPECT_TRUE(in_guard(d)) << x << " - " << y << " = " << d;
    }
  // The upper end is tight: one unit beyond it, x - (-x) leaves the guard.
  const double beyond = std::nextafter(0x1p299, 1e308);
  EXPECT_FALSE(in_guard(beyond - (-beyond)));
}

TEST(Exact, FilterWithoutTheGuardTestDecidesAsTheGuardedOne) {
  // Differences of tame points: near-coplanar (tiny z), exactly coplanar, axis-aligned, and far apart.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-190, 280);
  int undecided = 0, zero = 0;
  for (int i = 0; i < test::cases(20000); ++i) {
    const double s = std::ldexp(1.0, scale(rng));
    const int kind = i % 4;
    std::array<std::array<double, 3>, 4> x;
    for (auto& p : x)
      for (int c = 0; c < 3; ++c) {
        double value = s * unit(rng);
        if (c == 2 && kind == 1) value = s * 0x1p-52 * unit(rng);  // nearly coplanar
        if (c == 2 && kind == 2) value = 0;                        // coplanar
        if (kind == 3) value = std::round(4 * unit(rng)) * s;      // on a lattice: many exact zeros
        p[c] = tame_coordinate(value) ? value : 0.0;
      }
    double p[3], q[3], r[3];
    for (int c = 0; c < 3; ++c) {
      p[c] = x[2][c] - x[1][c];
      q[c] = x[0][c] - x[1][c];
      r[c] = x[3][c] - x[1][c];
    }
    double guarded_value = 0, free_value = 0;
    const int guarded = orientation_filter<true>(p, q, r, guarded_value);
    const int free = orientation_filter<false>(p, q, r, free_value);
    ASSERT_EQ(guarded, free) << i;
    ASSERT_EQ(guarded_value, free_value) << i;
    undecided += guarded == kUndecided;
    zero += guarded == 0;
  }
  // The cases reach the filter's three outcomes (not only the easy ones).
  EXPECT_GT(undecided, 0);
  EXPECT_GT(zero, 0);
}

TEST(Exact, TameCoordinateRejectsNanInfinitiesAndMagnitudesOutsideTheRange) {
  for (double x : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity(), std::nextafter(0x1p-200, 0.0), 0x1p-1074, -0x1p-1022,
                   std::nextafter(0x1p299, 1e308), 0x1p300, -std::numeric_limits<double>::max()})
    EXPECT_FALSE(tame_coordinate(x)) << x;
  for (double x : {0.0, -0.0, 0x1p-200, -0x1p299, 1e-60, 1e90}) EXPECT_TRUE(tame_coordinate(x)) << x;
}

}  // namespace
}  // namespace hinge::fast
