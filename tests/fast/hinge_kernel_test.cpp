// The per-hinge kernel (hinge/fast/hinge_kernel.hpp): against an independent high-precision evaluation
// (hinge::reference in MPFR at 256 bits), against hinge::reference in the same scalar type, the check
// values and branch cut of docs/contract.md, exact validity decisions with the reference's messages, and
// exact power-of-two scaling. Errors in units of the type's unit roundoff (tests/support/tolerance.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "fast_support.hpp"
#include "hinge/fast/faithful.hpp"
#include "hinge/fast/hinge_kernel.hpp"
#include "hinge/fast/isa.hpp"
#include "hinge/reference/evaluate.hpp"
#include "src/generic_kernel.hpp"  // detail::wide_range_kernel
#include "support/hinges.hpp"
#include "support/tolerance.hpp"

namespace hinge::fast {
namespace {

using reference::ThetaDerivatives;

using test::exact;

TEST(HingeKernel, CheckValuesOfTheConventions) {
  const auto x = test::flat_hinge();
  const HingeDerivatives<double> d = hinge_derivatives<double>(x);
  EXPECT_EQ(d.theta, 0.0);
  EXPECT_FALSE(d.on_branch_cut);
  // d theta / d x0 = -n / h0 = (0, 0, -1) (eq. (4)), exactly: every quantity here is exact in double.
  EXPECT_EQ(d.grad[0], 0.0);
  EXPECT_EQ(d.grad[1], 0.0);
  EXPECT_EQ(d.grad[2], -1.0);
  auto lifted = x;
  lifted[2] = 0.25;  // x0 along +n: theta negative
  EXPECT_LT(hinge_derivatives<double>(lifted).theta, 0.0);
}

TEST(HingeKernel, DoubleMatchesMpfr256OnWellShapedHinges) {
  // The bounds for the fast kernel: worst 4, median 2 units of 2^-53, normwise, in the Hessian.
  // The gradient and theta are formed from the same once-rounded quantities with two or three more
  // roundings each: 4 units as well (measured worst 3.3 and 2.4 on 20000 hinges).
  const auto hinges = test::well_shaped_hinges(test::cases(400), 21);
  std::vector<double> errors;
  double worst_grad = 0, worst_theta = 0;
  for (const auto& x : hinges) {
    const HingeDerivatives<double> d = hinge_derivatives<double>(x);
    const ThetaDerivatives<mpfr> e = exact(x);
    const double h = test::normwise_units(d.hess, e.hess, 0x1p-53);
    const double g = test::normwise_units(d.grad, e.grad, 0x1p-53);
    const double t = std::fabs(d.theta - to_double(e.angle.theta)) / std::fabs(to_double(e.angle.theta)) / 0x1p-53;
    errors.push_back(h);
    worst_grad = std::max(worst_grad, g);
    worst_theta = std::max(worst_theta, t);
    EXPECT_LE(h, 4) << test::describe(x);
    EXPECT_LE(g, 4) << test::describe(x);
    EXPECT_LE(t, 4) << test::describe(x);
  }
  std::sort(errors.begin(), errors.end());
  EXPECT_LE(errors[errors.size() / 2], 2) << "median Hessian error, units of 2^-53";
  RecordProperty("worst_hessian_units", std::to_string(errors.back()));
  RecordProperty("median_hessian_units", std::to_string(errors[errors.size() / 2]));
}

TEST(HingeKernel, DoubleStaysWithinFourUnitsOnRandomTrianglesNearlyFlatOrNot) {
  // Uniformly random vertices in [-1, 1]^3 (triangles of every shape, hinge edges of every relative
  // length), half of them made parallelograms, x3 = (x1 + x2) - x0 (rounded) plus 2^-k, k in 10 .. 60:
  // nearly flat, where eq. (6)'s central blocks cancel. The bound of DoubleMatchesMpfr256OnWellShapedHinges:
  // 4 units (a hinge edge below 1/2 of the longest on such a hinge takes the faithful mode: measured worst
  // 4.3 before, 2.7 with it, on 3000 such hinges; the deep run of this test, 4000 hinges: 2.4).
  std::mt19937_64 rng(61);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  double worst = 0;
  for (int i = 0; i < test::cases(400); ++i) {
    std::array<double, 12> x;
    for (double& c : x) c = u(rng);
    if (i % 2)
      for (int c = 0; c < 3; ++c) x[9 + c] = (x[3 + c] + x[6 + c]) - x[c] + std::ldexp(u(rng), -10 - 10 * (i / 2 % 6));
    HingeDerivatives<double> d;
    try {
      d = hinge_derivatives<double>(x);
    } catch (const InputError&) {
      continue;
    }
    const ThetaDerivatives<mpfr> e = exact(x);
    const double theta = to_double(e.angle.theta);
    const double t = theta == 0 ? 0 : std::fabs(d.theta - theta) / std::fabs(theta) / 0x1p-53;
    const double error =
        std::max({t, test::normwise_units(d.grad, e.grad, 0x1p-53), test::normwise_units(d.hess, e.hess, 0x1p-53)});
    EXPECT_LE(error, 4) << test::describe(x);
    worst = std::max(worst, error);
    ++checked;
  }
  EXPECT_GE(checked, test::cases(400) * 9 / 10);
  RecordProperty("worst_units", std::to_string(worst));
}

template <class Scalar>
class FastScalarTypes : public ::testing::Test {};
using Types = ::testing::Types<float, long double, dd, qd,
#if HINGE_HAVE_FLOAT128
                               float128,
#endif
                               bin128, mpfr>;
TYPED_TEST_SUITE(FastScalarTypes, Types);

TYPED_TEST(FastScalarTypes, MatchesMpfr256InItsOwnUnits) {
  using Scalar = TypeParam;
  // float: the quantities are computed in double and rounded once (as for double: bound 8 units, measured
  // worst 2.3). The other types compute them in their own format (no wider type at hand), where
  // near-folded hinges amplify their errors several fold: 32 units (measured worst 10), the bound the
  // reference's own test uses for them.
  const double bound = std::same_as<Scalar, float> ? 8 : 32;
  for (const auto& x : test::well_shaped_hinges(test::cases(40), 22)) {
    if constexpr (std::same_as<Scalar, mpfr>) set_mpfr_bits(113);
    const HingeDerivatives<Scalar> d = hinge_derivatives<Scalar>(x);
    const double u = test::unit_roundoff_double<Scalar>();
    const ThetaDerivatives<mpfr> e = exact(x);
    EXPECT_LE(test::normwise_units(d.hess, e.hess, u), bound) << scalar_name<Scalar>() << " " << test::describe(x);
    EXPECT_LE(test::normwise_units(d.grad, e.grad, u), bound) << scalar_name<Scalar>() << " " << test::describe(x);
  }
}

TYPED_TEST(FastScalarTypes, PowerOfTwoScalingIsExact) {
  using Scalar = TypeParam;
  if constexpr (!std::same_as<Scalar, float>) {  // float's range holds no result of a hinge at 2^+-300
    // As for double (below): the results of x 2^k are exactly those of x, with grad theta times 2^-k and
    // Hess theta times 2^-2k. dd and qd (double's exponent range) rescale their edges to do so; the other
    // types' ranges hold every intermediate, and scaling by a power of two changes no rounding.
    for (const auto& x : test::well_shaped_hinges(10, 25)) {
      if constexpr (std::same_as<Scalar, mpfr>) set_mpfr_bits(113);
      const HingeDerivatives<Scalar> d = hinge_derivatives<Scalar>(x);
      for (int k : {-450, -300, 300, 450}) {
        std::array<double, 12> y;
        for (int i = 0; i < 12; ++i) y[i] = std::ldexp(x[i], k);
        const HingeDerivatives<Scalar> t = hinge_derivatives<Scalar>(y);
        using std::ldexp;
        ASSERT_TRUE(t.theta == d.theta) << k << " " << test::describe(x);
        for (int i = 0; i < 12; ++i) ASSERT_TRUE(t.grad[i] == ldexp(d.grad[i], -k)) << k << " " << i;
        for (int i = 0; i < 144; ++i) ASSERT_TRUE(t.hess.data()[i] == ldexp(d.hess.data()[i], -2 * k)) << k << " " << i;
      }
    }
  }
}

TEST(HingeKernel, Bin128MatchesReferenceBin128) {
  // Same scalar type, independent formulas (q_j and a_j here, eq. (6) block by block there): each within
  // 32 units of 2^-113 of the exact values (previous test and the reference's), so 64 apart.
  for (const auto& x : test::well_shaped_hinges(test::cases(40), 23)) {
    const HingeDerivatives<bin128> f = hinge_derivatives<bin128>(x);
    const ThetaDerivatives<bin128> r = reference::theta_derivatives<bin128>(x);
    const double u = test::unit_roundoff_double<bin128>();
    EXPECT_LE(test::normwise_units(f.hess, r.hess, u), 64) << test::describe(x);
    EXPECT_LE(test::normwise_units(f.grad, r.grad, u), 64) << test::describe(x);
  }
}

TEST(HingeKernel, FoldedFlatIsPlusPiExactly) {
  // x3 == x0: the two faces coincide, folded onto each other (docs/contract.md: theta = +pi, never -pi).
  const std::array<double, 12> folded{0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, 1, 0};
  for (const auto& x : {folded, std::array<double, 12>{0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.25, 2, 0}}) {
    const HingeDerivatives<double> d = hinge_derivatives<double>(x);
    EXPECT_EQ(d.theta, std::numbers::pi);
    EXPECT_TRUE(d.on_branch_cut);
    const HingeDerivatives<bin128> q = hinge_derivatives<bin128>(x);
    EXPECT_TRUE(q.on_branch_cut);
    EXPECT_EQ(to_double(q.theta), std::numbers::pi);
  }
  // Slightly off the cut on either side: theta near +pi or near -pi, decided exactly.
  auto above = folded, below = folded;
  above[11] = 0x1p-40;
  below[11] = -0x1p-40;
  const double ta = hinge_derivatives<double>(above).theta, tb = hinge_derivatives<double>(below).theta;
  EXPECT_GT(std::fabs(ta), 3.14);
  EXPECT_GT(std::fabs(tb), 3.14);
  EXPECT_EQ(std::signbit(ta), !std::signbit(tb));
  EXPECT_EQ(std::signbit(ta), std::signbit(to_double(exact(above).angle.theta)));
}

std::string input_error(auto&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(HingeKernel, DegenerateHingesAreErrorsWithTheReferenceMessages) {
  std::vector<std::array<double, 12>> bad = {
      {0.5, 1, 0, 1, 0, 0, 1, 0, 0, 0.5, -1, 0},               // x1 == x2
      {0, 0, 0, 1, 0, 0, 2, 0, 0, 0.5, -1, 0},                 // upper collinear
      {0.5, 1, 0, 0, 0, 0, 1, 0, 0, 3, 0, 0},                  // lower collinear
      {0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, NAN, 0},              // not finite
      {0.1, 0.1 + 0x1p-52, 0, 0, 0, 0, 1, 1, 0, 0.5, -1, 0}};  // upper nearly collinear: fine
  for (const auto& x : bad) {
    const std::string f = input_error([&] { hinge_derivatives<double>(x); });
    const std::string r = input_error([&] { reference::theta_derivatives<double>(x); });
    EXPECT_EQ(f, r) << test::describe(x);
    EXPECT_EQ(input_error([&] { hinge_derivatives<bin128>(x); }), r) << test::describe(x);
  }
}

TEST(HingeKernel, PowerOfTwoScalingIsExact) {
  // theta is invariant under x -> 2^k x, grad theta scales by 2^-k and Hess theta by 2^-2k; the kernel
  // scales internally by powers of two only, so the results are exactly those of the unscaled hinge.
  for (const auto& x : test::well_shaped_hinges(20, 24)) {
    const HingeDerivatives<double> d = hinge_derivatives<double>(x);
    for (int k : {-700, -250, 250, 700}) {
      std::array<double, 12> y;
      for (int i = 0; i < 12; ++i) y[i] = std::ldexp(x[i], k);
      const HingeDerivatives<double> s = hinge_derivatives<double>(y);
      EXPECT_EQ(s.theta, d.theta) << k;
      for (int i = 0; i < 12; ++i) EXPECT_EQ(s.grad[i], std::ldexp(d.grad[i], -k)) << k;
      for (int i = 0; i < 144; ++i) EXPECT_EQ(s.hess.data()[i], std::ldexp(d.hess.data()[i], -2 * k)) << k;
    }
  }
}

TEST(HingeKernel, HessianIsExactlySymmetricAndGradientSumsToZero) {
  for (const auto& x : test::well_shaped_hinges(50, 25)) {
    const HingeDerivatives<double> d = hinge_derivatives<double>(x);
    EXPECT_EQ(d.hess, d.hess.transpose());
    // Translation null space: the four vertex gradients cancel up to the roundings of their terms.
    const Eigen::Vector3d sum =
        d.grad.segment<3>(0) + d.grad.segment<3>(3) + d.grad.segment<3>(6) + d.grad.segment<3>(9);
    EXPECT_LE(sum.norm(), 8 * 0x1p-53 * d.grad.norm()) << test::describe(x);
  }
}

// ---- ranges: docs/testing.md findings 2 and 3, extreme shapes, extreme scales ----------------------

ThetaDerivatives<mpfr> exact_with_bits(const std::array<double, 12>& x, unsigned bits) {
  set_mpfr_bits(bits);
  return reference::theta_derivatives<mpfr>(x);
}

template <class Scalar>
bool all_finite(const HingeDerivatives<Scalar>& d) {
  using std::isfinite;
  if (!isfinite(d.theta)) return false;
  for (const Scalar& v : d.grad)
    if (!isfinite(v)) return false;
  for (const Scalar& v : d.hess.reshaped())
    if (!isfinite(v)) return false;
  return true;
}

// x times 2^k, when every coordinate scales exactly (no overflow, no subnormal).
std::optional<std::array<double, 12>> scaled_exactly(const std::array<double, 12>& x, int k) {
  std::array<double, 12> y;
  for (int i = 0; i < 12; ++i) {
    y[i] = std::ldexp(x[i], k);
    if (!std::isfinite(y[i]) || std::ldexp(y[i], -k) != x[i]) return std::nullopt;
  }
  return y;
}

// theta unchanged, grad times 2^-k, Hess times 2^-2k, bit for bit (also where that overflows or underflows).
void expect_scaled_exactly(const HingeDerivatives<double>& d, const HingeDerivatives<double>& s, int k,
                           const std::array<double, 12>& x) {
  EXPECT_EQ(s.theta, d.theta) << k << " " << test::describe(x);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(s.grad[i], std::ldexp(d.grad[i], -k)) << k << " " << test::describe(x);
  for (int i = 0; i < 144; ++i)
    EXPECT_EQ(s.hess.data()[i], std::ldexp(d.hess.data()[i], -2 * k)) << k << " " << test::describe(x);
}

// docs/testing.md, finding 2: a hinge edge 5e-12 times the longest edge, at the size where the kernel
// stops rescaling (largest difference near 2^-200). 1 / (l_0^3 2A) overflowed; r_0 = m_0 / l_0^2 does not.
const std::array<double, 12> kFinding2{0,
                                       -7.7836328544510523e-73,
                                       3.1134531417804208e-61,
                                       0,
                                       0,
                                       0,
                                       0,
                                       1.5567265708902105e-72,
                                       0,
                                       1.5560780158936893e-62,
                                       -7.7836328544510523e-73,
                                       -3.1095621360807212e-61};
// docs/testing.md, finding 3: kappa_shape 2e11 (a short hinge edge), theta = -0.05.
const std::array<double, 12> kFinding3{0,
                                       -2.4545467326488632e-103,
                                       9.8181869305954537e-92,
                                       0,
                                       0,
                                       0,
                                       0,
                                       4.9090934652977265e-103,
                                       0,
                                       4.9070482653539194e-93,
                                       -2.4545467326488632e-103,
                                       -9.8059167535386641e-92};
// A hinge edge about 0.34 of the longest edge on a hinge 2^-10 from flat.
const std::array<double, 12> kShortishNearlyFlat{0.1, 1, 0, 0, 0, 0, 0.35, 0, 0, 0.2, -1, 0x1p-10};

TEST(HingeKernel, ShortHingeEdgeAtTheRescalingThresholdIsFiniteAndAccurate) {
  const HingeDerivatives<double> d = hinge_derivatives<double>(kFinding2);
  ASSERT_TRUE(all_finite(d)) << test::describe(kFinding2);
  const ThetaDerivatives<mpfr> e = exact(kFinding2);
  // The fast kernel's class on hard hinges (tolerance.hpp, fast_units_per_kappa<double>): c kappa_shape,
  // c = 4: the summaries rounded once, eq. (6) amplifying their errors by up to kappa_shape.
  const double bound = 4 * test::shape_condition_number(kFinding2);
  EXPECT_LE(test::normwise_units(d.hess, e.hess, 0x1p-53), bound);
  EXPECT_LE(test::normwise_units(d.grad, e.grad, 0x1p-53), bound);
  RecordProperty("hessian_units", std::to_string(test::normwise_units(d.hess, e.hess, 0x1p-53)));
  RecordProperty("gradient_units", std::to_string(test::normwise_units(d.grad, e.grad, 0x1p-53)));
  // Scaled so that the largest edge component lies on either side of 2^-200 (rescaled or not): the
  // same results, scaled exactly.
  for (int k = -4; k <= 4; ++k) {
    const auto y = scaled_exactly(kFinding2, k);
    ASSERT_TRUE(y);
    const HingeDerivatives<double> s = hinge_derivatives<double>(*y);
    ASSERT_TRUE(all_finite(s)) << k;
    expect_scaled_exactly(d, s, k, kFinding2);
  }
}

TEST(HingeKernel, HingeEdgesBelowAQuarterTakeTheFaithfulModeAndStayWithinOneUnit) {
  // Below 1/4 of the longest edge the double kernel evaluates the hinge again in the faithful mode
  // (hinge_kernel_lanes.hpp: eq. (6)'s central blocks reached 9.4 units of 2^-53 below 1/8 in double, 4.2
  // between 1/8 and 1/4 on nearly flat hinges). The results are the faithful mode's, bit for bit, and
  // within 1 unit of 2^-53 of MPFR at 256 bits (rounded to double: the final rounding alone,
  // hinge/fast/faithful.hpp).
  int taken = 0;
  for (const auto& base : test::well_shaped_hinges(test::cases(60), 41)) {
    for (int k : {2, 4, 9, 17, 30}) {  // 2^-2 of a well-shaped hinge edge: often below 1/4, 2^-4 and less always
      std::array<double, 12> x = base;
      for (int c = 0; c < 3; ++c) x[6 + c] = x[3 + c] + std::ldexp(base[6 + c] - base[3 + c], -k);  // x2 towards x1
      HingeDerivatives<double> d;
      try {
        d = hinge_derivatives<double>(x);
      } catch (const InputError&) {
        continue;  // x2 rounded onto x1 or the line of a triangle
      }
      // The kernel's test: 16 l0^2 < the largest squared edge length (of the five), in double.
      auto squared = [&x](int a, int b) {
        double s = 0;
        for (int c = 0; c < 3; ++c) s += (x[3 * a + c] - x[3 * b + c]) * (x[3 * a + c] - x[3 * b + c]);
        return s;
      };
      const double l0 = squared(2, 1),
                   longest = std::max({squared(0, 2), squared(1, 0), squared(3, 2), squared(1, 3), l0});
      if (!(16 * l0 < 0.99 * longest)) continue;  // not short (or too near the threshold to tell)
      const HingeDerivatives<double> f = faithful_hinge_derivatives(x);
      ASSERT_EQ(d.theta, f.theta) << test::describe(x);
      for (int i = 0; i < 12; ++i) ASSERT_EQ(d.grad[i], f.grad[i]) << test::describe(x);
      for (int i = 0; i < 144; ++i) ASSERT_EQ(d.hess.data()[i], f.hess.data()[i]) << test::describe(x);
      const ThetaDerivatives<mpfr> e = exact(x);
      EXPECT_LE(test::normwise_units(d.hess, e.hess, 0x1p-53), 1) << test::describe(x);
      EXPECT_LE(test::normwise_units(d.grad, e.grad, 0x1p-53), 1) << test::describe(x);
      ++taken;
    }
  }
  EXPECT_GE(taken, test::cases(60) * 4);  // k = 4, 9, 17, 30 are always short; invalid draws are rare
}

TEST(HingeKernel, NearlyFlatHingesWithAHingeEdgeBelowAHalfTakeTheFaithfulMode) {
  // Between 1/4 and 1/2 of the longest edge, within ~2^-6 of flat (or folded): the faithful mode, bit for
  // bit (hinge_kernel_double.cpp); the same hinge well bent stays on the plain path.
  const HingeDerivatives<double> d = hinge_derivatives<double>(kShortishNearlyFlat),
                                 f = faithful_hinge_derivatives(kShortishNearlyFlat);
  EXPECT_EQ(d.theta, f.theta);
  for (int i = 0; i < 12; ++i) ASSERT_EQ(d.grad[i], f.grad[i]);
  for (int i = 0; i < 144; ++i) ASSERT_EQ(d.hess.data()[i], f.hess.data()[i]);
  std::array<double, 12> bent = kShortishNearlyFlat;
  bent[11] = 0.5;  // x3 lifted: theta about 0.5
  const HingeDerivatives<double> p = hinge_derivatives<double>(bent), q = faithful_hinge_derivatives(bent);
  int differ = 0;
  for (int i = 0; i < 144; ++i) differ += p.hess.data()[i] != q.hess.data()[i];
  EXPECT_GT(differ, 0) << "the plain kernel's own rounding differs from the faithful mode in some entry";
  const ThetaDerivatives<mpfr> e = exact(kShortishNearlyFlat);
  EXPECT_LE(test::normwise_units(d.hess, e.hess, 0x1p-53), 1);  // the faithful mode's bound
}

// Nearly flat (theta ~ 2^-60 relative to the hinge's size) at scales 2^-400, 1, 2^400: the types of at most
// 113 bits take theta from the exact hinge determinant, whose value (2^1140 at 2^400) lies outside double's
// range: theta rounded to double within 2 units (the wider types' bound, docs/hard-cases.md) and finite.
template <class Scalar>
void check_nearly_flat_theta_at_every_scale() {
  for (int k : {-400, 0, 400}) {
    std::array<double, 12> x{0.3, 1, 0, 0, 0, 0, 1, 0, 0, 0.6, -1.1, 0x1p-60};
    for (double& c : x) c = std::ldexp(c, k);
    const double theta = to_double(hinge_derivatives<Scalar>(x).theta), want = to_double(exact(x).angle.theta);
    EXPECT_LE(std::fabs(theta - want) / std::fabs(want) / 0x1p-53, 2) << scalar_name<Scalar>() << " at 2^" << k;
  }
}

TEST(HingeKernel, NearlyFlatThetaKeepsItsDigitsAtEveryScaleInTheWiderTypes) {
  check_nearly_flat_theta_at_every_scale<long double>();
  check_nearly_flat_theta_at_every_scale<dd>();
#if HINGE_HAVE_FLOAT128
  check_nearly_flat_theta_at_every_scale<float128>();
#endif
  check_nearly_flat_theta_at_every_scale<bin128>();
}

TEST(HingeKernel, Bin128ShortHingeEdgeKeepsItsDigits) {
  const HingeDerivatives<bin128> d = hinge_derivatives<bin128>(kFinding3);
  ASSERT_TRUE(all_finite(d));
  const ThetaDerivatives<mpfr> e = exact(kFinding3);
  const double u = test::unit_roundoff_double<bin128>();
  const double g = test::normwise_units(d.grad, e.grad, u), h = test::normwise_units(d.hess, e.hess, u);
  RecordProperty("gradient_units", std::to_string(g));
  RecordProperty("hessian_units", std::to_string(h));
  // The property suite's bound for bin128 (tolerance.hpp): 12 kappa. The law of cosines gave 1.8e22
  // units in the gradient here (kappa_shape^2 u: its cancellation times the gradient's own condition).
  const double kappa = test::condition_number(kFinding3);
  EXPECT_LE(g, 12 * kappa);
  EXPECT_LE(h, 12 * kappa);
  // Stronger, for this hinge: its edge lies along an axis, so e_0 . e_i, e_2 x e_0 and e_0 x C have one
  // product per component (exact up to one rounding): the stencil is within a few units, and eq. (6)
  // amplifies that by at most kappa_angle = 1 / sin(0.05) = 20 in the Hessian. 32 units, the bound of
  // well-shaped hinges (MatchesMpfr256InItsOwnUnits), times 20 for the Hessian.
  EXPECT_LE(g, 32);
  EXPECT_LE(h, 32 * 20);
}

// Shapes far beyond the double-double path's range (triangles()): the wide-range kernel (long double,
// exact normals). Sized so that the exact results are normal doubles; compared with the reference in
// MPFR at 2048 bits (the coordinates span 2^600: 256 bits would round the edges).
struct ExtremeHinge {
  const char* name;
  std::array<double, 12> x;
};
std::vector<ExtremeHinge> extreme_hinges() {
  const double big = 0x1p600;
  return {
      // A needle in general position: apex x0 at distance ~1 from the hinge edge of length ~2^601 (an
      // altitude 2^-600 times the longest edge); x0 - x2 is not a long double: rounded, the triangle
      // would be degenerate.
      {"needle", {1, -1, 0, -big, -big, -big, big, big, big, big, -2 * big, 0.5 * big}},
      // A hinge edge of length ~1, 2^-600 times the other edges (apexes in general directions).
      {"short hinge edge", {0.25 * big, big, 0.5 * big, 0, 0, 0, 1, 0.5, -0.25, 1.5 * big, -big, 0.5 * big}},
      // Both at once: the upper triangle a needle (altitude ~1 on a hinge edge of 2^300), the lower one
      // with that hinge edge 2^-300 times its other edges.
      {"needle on a short edge", {0x1p299, 1, 0.5, 0, 0, 0, 0x1p300, 0, 0, 0.3 * big, -big, 0.7 * big}},
  };
}

TEST(HingeKernel, ExtremeShapesAreFiniteAndAccurate) {
  for (const ExtremeHinge& h : extreme_hinges()) {
    const HingeDerivatives<double> d = hinge_derivatives<double>(h.x);
    ASSERT_TRUE(all_finite(d)) << h.name;
    const ThetaDerivatives<mpfr> e = exact_with_bits(h.x, 2048);
    const double t =
        std::fabs(d.theta - to_double(e.angle.theta)) / std::max(1.0, std::fabs(to_double(e.angle.theta))) / 0x1p-53;
    const double g = test::normwise_units(d.grad, e.grad, 0x1p-53), H = test::normwise_units(d.hess, e.hess, 0x1p-53);
    RecordProperty(std::string(h.name) + " units (theta, grad, hess)",
                   std::to_string(t) + ", " + std::to_string(g) + ", " + std::to_string(H));
    // kappa_shape is 2^600 here: the general bound says nothing. These shapes have no cancellation
    // beyond the normals (exact): every quantity within a few units of 2^-64, rounded to double once.
    // 4 units, the fast kernel's bound on well-shaped hinges.
    EXPECT_LE(t, 4) << h.name;
    EXPECT_LE(g, 4) << h.name;
    EXPECT_LE(H, 4) << h.name;
    // And exactly invariant under power-of-two scaling, here too (not scaled down by much: some Hessian
    // entries, ~2^-1200, underflow at this size and would reappear, rounded at another scale).
    for (int k : {-7, 9, 150}) {
      const auto y = scaled_exactly(h.x, k);
      if (!y) continue;
      expect_scaled_exactly(d, hinge_derivatives<double>(*y), k, h.x);
    }
  }
}

TEST(HingeKernel, WideRangeKernelMatchesMpfr256OnWellShapedHinges) {
  // The fallback on ordinary hinges (where MPFR at 256 bits is exact to the last bit of double): the
  // quantities in long double (2^-64), eq. (6) in long double, each result rounded once: within the
  // fast kernel's bounds, worst 4 and median 2 units of 2^-53.
  std::vector<double> errors;
  for (const auto& x : test::well_shaped_hinges(test::cases(100), 26)) {
    HingeDerivatives<double> d;
    detail::wide_range_kernel<double>(x, true, d);
    const ThetaDerivatives<mpfr> e = exact(x);
    const double h = test::normwise_units(d.hess, e.hess, 0x1p-53);
    errors.push_back(h);
    EXPECT_LE(h, 4) << test::describe(x);
    EXPECT_LE(test::normwise_units(d.grad, e.grad, 0x1p-53), 4) << test::describe(x);
  }
  std::sort(errors.begin(), errors.end());
  EXPECT_LE(errors[errors.size() / 2], 2) << "median Hessian error, units of 2^-53";
  RecordProperty("worst_hessian_units", std::to_string(errors.back()));
  RecordProperty("median_hessian_units", std::to_string(errors[errors.size() / 2]));
}

TEST(HingeKernel, PowerOfTwoScalingIsExactOverTheWholeExponentRange) {
  // Near 2^-1000 the Hessian (~2^2000) overflows: it must then be infinite, never NaN; near 2^1000 it
  // underflows (and coordinates near 2^1015 make differences overflow: the kernel quarters them).
  std::vector<std::array<double, 12>> hinges = test::well_shaped_hinges(20, 27, 0);
  hinges.push_back(kFinding2);
  hinges.push_back(test::flat_hinge());
  for (const auto& x : hinges) {
    const HingeDerivatives<double> d = hinge_derivatives<double>(x);
    for (int k : {-1000, -900, -600, 600, 900, 1000, 1015}) {
      const auto y = scaled_exactly(x, k);
      if (!y) continue;
      const HingeDerivatives<double> s = hinge_derivatives<double>(*y);
      for (int i = 0; i < 144; ++i) EXPECT_FALSE(std::isnan(s.hess.data()[i])) << k;
      expect_scaled_exactly(d, s, k, x);
    }
  }
}

// The double kernel is compiled for AVX-512, AVX2 and the baseline x86-64 (src/hinge_kernel_double.cpp)
// and promises the same bits from each: lane-by-lane IEEE operations in the same order. Checked on the
// processor's instruction sets, over well-shaped hinges, the extreme shapes and the findings above (the
// rescaled and wide-range paths), and the rejections.
// Well-shaped hinges, the extreme shapes and the findings above scaled far (the rescaled and wide-range
// paths), the flat hinge and the folded flat one (theta = +pi): the cases of the same-bits tests.
std::vector<std::array<double, 12>> same_bits_hinges(int well_shaped) {
  std::vector<std::array<double, 12>> hinges = test::well_shaped_hinges(well_shaped, 27);
  for (const ExtremeHinge& h : extreme_hinges()) hinges.push_back(h.x);
  for (int k : {-700, -250, 250, 700})
    for (const auto& x : {kFinding2, kFinding3, test::flat_hinge()})
      if (const auto y = scaled_exactly(x, k)) hinges.push_back(*y);
  hinges.push_back(test::flat_hinge());
  hinges.push_back({0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, 1, 0});           // folded flat: theta = +pi
  hinges.push_back({0.3, 1, 0, 0, 0, 0, 1, 0, 0, 0.6, -1.1, 0x1p-60});  // nearly flat: theta from the determinant
  hinges.push_back(kShortishNearlyFlat);  // l0 / L about 0.35, nearly flat: the faithful mode
  return hinges;
}

bool same_bits(const HingeDerivatives<double>& a, const HingeDerivatives<double>& b) {
  return std::bit_cast<std::uint64_t>(a.theta) == std::bit_cast<std::uint64_t>(b.theta) &&
         std::bit_cast<std::uint64_t>(a.tan_half_theta) == std::bit_cast<std::uint64_t>(b.tan_half_theta) &&
         a.on_branch_cut == b.on_branch_cut && std::memcmp(a.grad.data(), b.grad.data(), sizeof(double) * 12) == 0 &&
         std::memcmp(a.hess.data(), b.hess.data(), sizeof(double) * 144) == 0;
}

TEST(HingeKernel, EveryInstructionSetGivesTheSameBits) {
  // The plain kernel and the faithful mode (hinge/fast/faithful.hpp).
  const std::vector<std::array<double, 12>> hinges = same_bits_hinges(test::cases(200));
  int compared = 0;
  auto kernel = [](bool faithful, Isa isa, const std::array<double, 12>& x, bool want_hessian,
                   HingeDerivatives<double>& d) {
    return faithful ? faithful_hinge_derivatives(isa, x, want_hessian, d) : hinge_derivatives(isa, x, want_hessian, d);
  };
  for (const auto& x : hinges)
    for (bool want_hessian : {true, false})
      for (bool faithful : {false, true}) {
        HingeDerivatives<double> base;
        ASSERT_TRUE(kernel(faithful, Isa::baseline, x, want_hessian, base));
        for (auto isa : {Isa::avx2, Isa::avx512}) {
          HingeDerivatives<double> d;
          if (!kernel(faithful, isa, x, want_hessian, d)) continue;
          ++compared;
          EXPECT_EQ(std::bit_cast<std::uint64_t>(d.theta), std::bit_cast<std::uint64_t>(base.theta))
              << test::describe(x);
          EXPECT_EQ(d.on_branch_cut, base.on_branch_cut);
          EXPECT_EQ(std::memcmp(d.grad.data(), base.grad.data(), sizeof(double) * 12), 0) << test::describe(x);
          EXPECT_EQ(std::memcmp(d.hess.data(), base.hess.data(), sizeof(double) * 144), 0) << test::describe(x);
        }
      }
  RecordProperty("comparisons", std::to_string(compared));
  // The same errors, with the same messages.
  for (const auto& bad : {std::array<double, 12>{0.5, 1, 0, 1, 0, 0, 1, 0, 0, 0.5, -1, 0},
                          std::array<double, 12>{0, 0, 0, 1, 0, 0, 2, 0, 0, 0.5, -1, 0},
                          std::array<double, 12>{0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, NAN, 0}})
    for (auto isa : {Isa::baseline, Isa::avx2, Isa::avx512})
      for (bool faithful : {false, true}) {
        HingeDerivatives<double> d;
        bool available = true;  // stays true when the kernel throws
        const std::string message = input_error([&] { available = kernel(faithful, isa, bad, true, d); });
        if (available) {
          EXPECT_EQ(message, input_error([&] { hinge_derivatives<double>(bad); }));
        }
      }
}

// Many hinges at once (with AVX-512 two at a time: lanes.hpp, Twice) give each hinge the bits it gets
// alone. The special cases sit between well-shaped hinges in both orders, so that each meets the pair
// kernel in either position, next to an ordinary hinge and next to another special one (a rare path in
// either hinge sends the pair one by one); the count is odd (the last hinge alone).
TEST(HingeKernel, ManyAtOnceGiveTheBitsOfOneAtATime) {
  const std::vector<std::array<double, 12>> special = same_bits_hinges(0);
  const std::vector<std::array<double, 12>> ordinary = test::well_shaped_hinges(test::cases(100), 31);
  std::vector<std::array<double, 12>> hinges;
  for (std::size_t i = 0; i < ordinary.size(); ++i) {
    hinges.push_back(ordinary[i]);
    if (i < special.size()) hinges.push_back(special[i]);
    if (i < special.size()) hinges.push_back(special[special.size() - 1 - i]);
  }
  hinges.insert(hinges.end(), special.begin(), special.end());
  if (hinges.size() % 2 == 0) hinges.push_back(ordinary[0]);
  ASSERT_GT(ordinary.size(), special.size());
  for (bool want_hessian : {true, false}) {
    std::vector<HingeDerivatives<double>> many(hinges.size());
    hinge_derivatives<double>(hinges, many, want_hessian);
    for (std::size_t i = 0; i < hinges.size(); ++i)
      EXPECT_TRUE(same_bits(many[i], hinge_derivatives<double>(hinges[i], want_hessian)))
          << i << ": " << test::describe(hinges[i]);
  }
  // The other scalar types evaluate one by one: the same.
  std::vector<HingeDerivatives<float>> floats(ordinary.size());
  hinge_derivatives<float>(ordinary, floats);
  for (std::size_t i = 0; i < ordinary.size(); ++i)
    EXPECT_EQ(floats[i].hess, hinge_derivatives<float>(ordinary[i]).hess);
}

TEST(HingeKernel, IntoTheCallersArraysGivesTheBitsOfHingeDerivatives) {
  // hinge_derivatives_into: the common path writes straight into the arrays, the rare ones (the special
  // hinges: folded, nearly flat, short hinge edges, rescaled) through a copy; Hess row-major.
  std::vector<std::array<double, 12>> hinges = same_bits_hinges(test::cases(200));
  const auto ordinary = test::well_shaped_hinges(test::cases(100), 37);
  hinges.insert(hinges.end(), ordinary.begin(), ordinary.end());
  for (const auto& x : hinges) {
    const HingeDerivatives<double> d = hinge_derivatives<double>(x);
    double theta = -1, grad[12], hess[144];
    std::fill(grad, grad + 12, -1.0), std::fill(hess, hess + 144, -1.0);
    hinge_derivatives_into(x, theta, grad, hess);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(theta), std::bit_cast<std::uint64_t>(d.theta)) << test::describe(x);
    EXPECT_EQ(std::memcmp(grad, d.grad.data(), sizeof grad), 0) << test::describe(x);
    bool same = true;
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j)
        same = same && std::bit_cast<std::uint64_t>(hess[12 * i + j]) == std::bit_cast<std::uint64_t>(d.hess(i, j));
    EXPECT_TRUE(same) << test::describe(x);
  }
  for (const auto& bad : {std::array<double, 12>{0.5, 1, 0, 1, 0, 0, 1, 0, 0, 0.5, -1, 0},
                          std::array<double, 12>{0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, NAN, 0}}) {
    double theta, grad[12], hess[144];
    EXPECT_EQ(input_error([&] { hinge_derivatives_into(bad, theta, grad, hess); }),
              input_error([&] { hinge_derivatives<double>(bad); }));
  }
}

TEST(HingeKernel, ManyAtOnceThrowForTheFirstFailingHingeInOrder) {
  std::vector<std::array<double, 12>> hinges = test::well_shaped_hinges(8, 33);
  const std::array<double, 12> zero_area{0, 0, 0, 1, 0, 0, 2, 0, 0, 0.5, -1, 0};
  const std::array<double, 12> not_finite{0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, NAN, 0};
  hinges[5] = zero_area;   // in the second place of a pair
  hinges[6] = not_finite;  // later: not reported
  std::vector<HingeDerivatives<double>> out(hinges.size());
  EXPECT_EQ(input_error([&] { hinge_derivatives<double>(hinges, out); }),
            input_error([&] { hinge_derivatives<double>(zero_area); }));
  hinges[4] = not_finite;  // now first, in the first place of a pair
  EXPECT_EQ(input_error([&] { hinge_derivatives<double>(hinges, out); }),
            input_error([&] { hinge_derivatives<double>(not_finite); }));
  out.pop_back();
  EXPECT_THROW(hinge_derivatives<double>(hinges, out), std::invalid_argument);
}

}  // namespace
}  // namespace hinge::fast
