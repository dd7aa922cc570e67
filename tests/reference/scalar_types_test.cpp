// Every scalar type evaluates the reference: against the same formulas in MPFR at 256 bits, in units of
// each type's own unit roundoff; exact Hessian symmetry; the translation null space (gradient sums to
// zero over the four vertices).
#include <gtest/gtest.h>

#include "hinge/reference/evaluate.hpp"
#include "support/hinges.hpp"
#include "support/tolerance.hpp"

namespace hinge::reference {
namespace {

template <class Scalar>
class ScalarTypes : public ::testing::Test {};
using Types = ::testing::Types<HINGE_SCALAR_TYPES>;  // every type this build has (hinge/core/scalar_list.hpp)
TYPED_TEST_SUITE(ScalarTypes, Types);

// The precision `mpfr` runs at in these tests, and the reference precision.
constexpr unsigned test_bits = 113, exact_bits = 256;

template <class Scalar>
ThetaDerivatives<Scalar> evaluate(const std::array<double, 12>& x) {
  if constexpr (std::same_as<Scalar, mpfr>) set_mpfr_bits(test_bits);
  return theta_derivatives<Scalar>(x);
}

ThetaDerivatives<mpfr> exact(const std::array<double, 12>& x) {
  set_mpfr_bits(exact_bits);
  return theta_derivatives<mpfr>(x);
}

TYPED_TEST(ScalarTypes, HessianMatchesMpfr256OnWellShapedHinges) {
  using Scalar = TypeParam;
  // float and double: the stencil is computed one format wider and rounded once (evaluate_impl.hpp);
  // measured worst 3.9 units on 2000 double hinges. The other types compute it in their own format,
  // where near-folded hinges amplify stencil errors about sixfold (measured worst 17 units for double
  // computed that way). Bounds: 8 units (the bound for double) and 32 units respectively.
  const double bound = (std::same_as<Scalar, float> || std::same_as<Scalar, double>) ? 8 : 32;
  double worst = 0;
  for (const auto& x : test::well_shaped_hinges(300, 11)) {
    const auto d = evaluate<Scalar>(x);
    const double u = test::unit_roundoff_double<Scalar>();
    const auto e = exact(x);
    const double err = test::normwise_units(d.hess, e.hess, u);
    worst = std::max(worst, err);
    ASSERT_LE(err, bound) << test::describe(x);
    ASSERT_LE(test::normwise_units(d.grad, e.grad, u), bound) << test::describe(x);
  }
  this->RecordProperty("worst_units", std::to_string(worst));
  std::cout << "[ measured ] " << scalar_name<Scalar>() << ": worst normwise Hessian error " << worst << " units\n";
}

TYPED_TEST(ScalarTypes, PowerOfTwoScalingIsExact) {
  using Scalar = TypeParam;
  if constexpr (!std::same_as<Scalar, float>) {  // float's range holds no result of a hinge at 2^+-300
    // theta is invariant under x -> 2^k x, grad theta scales by 2^-k and Hess theta by 2^-2k
    // (proofs/invariance.md). The built-in types and dd and qd (double's exponent range) rescale their
    // edges by a power of two; the others' ranges hold every intermediate, where scaling by a power of
    // two changes no rounding: the results are exactly those of the unscaled hinge, scaled.
    for (const auto& x : test::well_shaped_hinges(10, 15)) {
      const auto d = evaluate<Scalar>(x);
      for (int k : {-450, -300, 300, 450}) {
        std::array<double, 12> y;
        for (int i = 0; i < 12; ++i) y[i] = std::ldexp(x[i], k);
        const auto t = evaluate<Scalar>(y);
        using std::ldexp;
        ASSERT_TRUE(t.angle.theta == d.angle.theta) << k << " " << test::describe(x);
        for (int i = 0; i < 12; ++i) ASSERT_TRUE(t.grad[i] == ldexp(d.grad[i], -k)) << k << " " << i;
        for (int i = 0; i < 144; ++i) ASSERT_TRUE(t.hess.data()[i] == ldexp(d.hess.data()[i], -2 * k)) << k << " " << i;
      }
    }
  }
}

TYPED_TEST(ScalarTypes, HessianIsExactlySymmetric) {
  for (const auto& x : test::well_shaped_hinges(50, 12)) {
    const auto d = evaluate<TypeParam>(x);
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < i; ++j) ASSERT_EQ(d.hess(i, j), d.hess(j, i)) << test::describe(x);  // by construction
  }
}

TYPED_TEST(ScalarTypes, GradientSumsToZeroOverTheFourVertices) {
  using Scalar = TypeParam;
  for (const auto& x : test::well_shaped_hinges(50, 13)) {
    const auto d = evaluate<Scalar>(x);
    const double u = test::unit_roundoff_double<Scalar>();
    for (int c = 0; c < 3; ++c) {
      double sum = 0, magnitude = 0;
      for (int v = 0; v < 4; ++v) {
        sum += to_double(d.grad[3 * v + c]);
        magnitude += std::abs(to_double(d.grad[3 * v + c]));
      }
      // Exact sum 0 (translation invariance, proofs/invariance.md); each term carries at most 32 units
      // (bound above), and the double sum of four adds 3 more: 35 u times the sum of magnitudes, plus
      // the rounding of the terms to double when u < 2^-53.
      ASSERT_LE(std::abs(sum), (35 * u + 0x1p-52) * magnitude) << test::describe(x);
    }
  }
}

TYPED_TEST(ScalarTypes, ThetaMatchesMpfr256) {
  using Scalar = TypeParam;
  for (const auto& x : test::well_shaped_hinges(100, 14)) {
    const auto d = evaluate<Scalar>(x);
    const auto e = exact(x);
    const double u = test::unit_roundoff_double<Scalar>();
    // atan2 of the products of a stencil rounded once: |theta| >= 0.05 on well-shaped hinges, and the
    // numerator and denominator carry a few units each: 16 u relative, plus the rounding to double.
    const double t = to_double(e.angle.theta);
    ASSERT_LE(std::abs(to_double(d.angle.theta) - t), (16 * u + 0x1p-53) * std::abs(t)) << test::describe(x);
  }
}

}  // namespace
}  // namespace hinge::reference
