// The sign filter of fast/src/exact.hpp: whenever it decides, its answer is the sign of the computed
// determinant (which the mesh path uses on the flat side without running the filter, assemble.hpp), and
// that determinant is hinge_determinant's, bit for bit.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "fast_support.hpp"
#include "src/exact.hpp"

namespace hinge::fast {
namespace {

int sign_of(double x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }

TEST(Exact, WheneverTheFilterDecidesItGivesTheSignOfTheComputedDeterminant) {
  // Differences of four points: general, nearly coplanar (the filter undecided), exactly coplanar (0),
  // on a lattice (many exact zeros), and at extreme scales (outside the filter's guard: undecided).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> scale(-1000, 1000);
  int undecided = 0, zero = 0, nonzero = 0;
  for (int i = 0; i < test::cases(20000); ++i) {
    const double s = std::ldexp(1.0, i % 5 == 4 ? scale(rng) : scale(rng) / 5);
    const int kind = i % 5;
    std::array<std::array<double, 3>, 4> x;
    for (auto& point : x)
      for (int c = 0; c < 3; ++c) {
        double value = s * unit(rng);
        if (c == 2 && kind == 1) value = s * 0x1p-52 * unit(rng);  // nearly coplanar
        if (c == 2 && kind == 2) value = 0;                        // coplanar
        if (kind == 3) value = std::round(4 * unit(rng)) * s;      // on a lattice
        point[c] = value;
      }
    double p[3], q[3], r[3];
    for (int c = 0; c < 3; ++c) {
      p[c] = x[2][c] - x[1][c];
      q[c] = x[0][c] - x[1][c];
      r[c] = x[3][c] - x[1][c];
    }
    double computed = 0;
    const int decided = orientation_filter(p, q, r, computed);
    const double determinant = hinge_determinant(p, q, r);
    ASSERT_TRUE(computed == determinant || (std::isnan(computed) && std::isnan(determinant))) << i;
    if (decided == kUndecided) {
      ++undecided;
      continue;
    }
    ASSERT_EQ(decided, sign_of(computed)) << i << ": " << computed;
    (decided == 0 ? zero : nonzero)++;
  }
  // The cases reach the filter's three outcomes (not only the easy ones).
  EXPECT_GT(undecided, 0);
  EXPECT_GT(zero, 0);
  EXPECT_GT(nonzero, 0);
}

}  // namespace
}  // namespace hinge::fast
