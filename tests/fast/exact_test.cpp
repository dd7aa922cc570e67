// The sign filter of fast/src/exact.hpp: whenever it decides, its answer is the sign of the computed
// determinant (which the mesh path uses on the flat side without running the filter, assemble.hpp), and
// that determinant is hinge_determinant's, bit for bit. The baseline's fused multiply-add without an FMA
// (fast/src/lanes.hpp, fused_without_fma) is the fused multiply-add, bit for bit.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "fast_support.hpp"
#include "src/exact.hpp"
#include "src/lanes.hpp"

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

TEST(Exact, FusedWithoutFmaAndTheProductErrorAreTheFusedMultiplyAddsBitForBit) {
  // Against std::fma (correctly rounded: the FMA instruction or glibc's). Operands over the kernels' range
  // and beyond (|a|, |b| up to 2^400; products down to 2^-800, so the product's error stays normal), every
  // sign, and the cases that decide the rounding: c cancelling the product to its last bits, c far below
  // the product, c far above, a sum that rounding to nearest twice would get wrong (case 5: without the
  // rounding to odd every one of them fails), products that are ties, zeros of both signs.
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> unit(1, 2);
  std::uniform_int_distribution<int> exponent(-400, 400), sign(0, 1), shape(0, 6);
  auto random = [&](int e) { return std::ldexp(unit(rng), e) * (sign(rng) ? -1 : 1); };
  int compared = 0, mismatches = 0;
  for (int round = 0; round < 200000; ++round) {
    Double4 a, b, c;
    for (int i = 0; i < 4; ++i) {
      a[i] = random(exponent(rng));
      b[i] = random(exponent(rng));
      const double p = a[i] * b[i];
      switch (shape(rng)) {
        case 0: c[i] = random(exponent(rng)); break;                                                     // anything
        case 1: c[i] = -p; break;                                                                        // cancels to e
        case 2: c[i] = -p + std::ldexp(p, -52) * (sign(rng) ? 1 : -1); break;                            // nearly
        case 3: c[i] = std::ldexp(p, -60 - static_cast<int>(rng() % 60)) * (sign(rng) ? 1 : -1); break;  // tail
        case 4: c[i] = std::ldexp(p, 40 + static_cast<int>(rng() % 30)); break;                          // far above
        case 5: {  // the double rounding that rounding to odd prevents: c + p a tie, the product's error
                   // -2^-(53+2j) just below it (a b = 2^-53 (1 - 2^-2j) 2^t, c = (1 + 2^-52) 2^t, odd)
          const int t = exponent(rng) / 2, j = 27 + static_cast<int>(rng() % 26), u = exponent(rng) / 4;
          const double s = sign(rng) ? 1 : -1;
          a[i] = s * std::ldexp(1 + std::ldexp(1, -j), u);
          b[i] = std::ldexp(1 - std::ldexp(1, -j), t - 53 - u);
          c[i] = s * std::ldexp(1 + std::ldexp(1, -52), t);
          break;
        }
        default:  // ties, zeros
          a[i] = 1 + std::ldexp(static_cast<double>(rng() % 1024), -10);
          b[i] = 1 + std::ldexp(1, -43);
          c[i] = (rng() % 3 == 0) ? -0.0 : (rng() % 2 ? 0.0 : -a[i]);
          if (rng() % 4 == 0) a[i] = sign(rng) ? 0.0 : -0.0;
      }
    }
    const Double4 got = fused_without_fma(a, b, c), p = a * b, error = product_error_without_fma(a, b, p);
    for (int i = 0; i < 4; ++i) {
      ++compared;
      const double want = std::fma(a[i], b[i], c[i]);
      if (std::bit_cast<std::uint64_t>(got[i]) != std::bit_cast<std::uint64_t>(want) && ++mismatches <= 5)
        ADD_FAILURE() << std::hexfloat << "a " << a[i] << " b " << b[i] << " c " << c[i] << ": " << got[i]
                      << " against " << want;
      const double want_error = std::fma(a[i], b[i], -p[i]);  // the exact error of the product
      if (std::bit_cast<std::uint64_t>(error[i]) != std::bit_cast<std::uint64_t>(want_error) && ++mismatches <= 5)
        ADD_FAILURE() << std::hexfloat << "a " << a[i] << " b " << b[i] << ": product error " << error[i] << " against "
                      << want_error;
    }
  }
  EXPECT_EQ(mismatches, 0) << "of " << compared;
}

}  // namespace
}  // namespace hinge::fast
