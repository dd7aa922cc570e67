// The baselines (hinge::baselines: autodiff, symbolic) compute what the atan2 definition says, in every
// scalar type: against the reference (eqs. (4)-(6), an independent formula) in MPFR at 256 bits, in units
// of each type's own unit roundoff, on well-shaped hinges; the three output levels agree; the contract's
// exact validity checks and branch cut.
#include <gtest/gtest.h>

#include "hinge/baselines/derivatives.hpp"
#include "hinge/reference/evaluate.hpp"
#include "support/hinges.hpp"
#include "support/tolerance.hpp"

namespace hinge::baselines {
namespace {

template <class Scalar>
class Baselines : public ::testing::Test {};
using Types = ::testing::Types<HINGE_SCALAR_TYPES>;  // every type this build has (hinge/core/scalar_list.hpp)
TYPED_TEST_SUITE(Baselines, Types);

constexpr unsigned test_bits = 113, exact_bits = 256;

template <class Scalar>
Derivatives<Scalar> evaluate(bool symbolic, const std::array<double, 12>& x, Outputs outputs = Outputs::hessian) {
  if constexpr (std::same_as<Scalar, mpfr>) set_mpfr_bits(test_bits);
  return symbolic ? symbolic_derivatives<Scalar>(x, outputs) : autodiff_derivatives<Scalar>(x, outputs);
}

template <class Scalar>
std::string test_name() {
  return std::same_as<Scalar, mpfr> ? "mpfr:" + std::to_string(test_bits) : scalar_name<Scalar>();
}

// The largest coordinate's magnitude.
double max_coordinate(const std::array<double, 12>& x) {
  double m = 0;
  for (const double c : x) m = std::max(m, std::abs(c));
  return m;
}

// The lengths of the five edges.
std::array<double, 5> edge_lengths(const std::array<double, 12>& x) {
  auto length = [&](int i, int j) {
    return std::hypot(x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1], x[3 * i + 2] - x[3 * j + 2]);
  };
  return {length(2, 1), length(0, 1), length(0, 2), length(3, 1), length(3, 2)};
}
double shortest_edge(const std::array<double, 12>& x) {
  const auto l = edge_lengths(x);
  return *std::min_element(l.begin(), l.end());
}
double longest_edge(const std::array<double, 12>& x) {
  const auto l = edge_lengths(x);
  return *std::max_element(l.begin(), l.end());
}

reference::ThetaDerivatives<mpfr> exact(const std::array<double, 12>& x) {
  set_mpfr_bits(exact_bits);
  return reference::theta_derivatives<mpfr>(x);
}

TYPED_TEST(Baselines, AgreeWithTheReferenceInMpfr256OnWellShapedHinges) {
  using Scalar = TypeParam;
  if constexpr (std::same_as<Scalar, mpfr>) set_mpfr_bits(test_bits);
  const double u = test::unit_roundoff_double<Scalar>();
  for (const bool symbolic : {false, true}) {
    double worst = 0;
    int tested = 0;
    for (const auto& x : test::well_shaped_hinges(200, 21)) {
      // The baselines do not rescale: the Hessian's chain rule squares (N . Nt)^2 + ((N x Nt) . e0)^2 / |e0|^2,
      // of size l^8, so an intermediate of size l^16 must lie in the type's range; float's (2^-126 ..
      // 2^128) holds it only for edges between about 2^-7 and 2^8 (beyond, the Hessian overflows or
      // underflows: the study counts that). The other types' ranges hold every hinge here.
      if constexpr (std::same_as<Scalar, float>) {
        const double l_max = longest_edge(x), l_min = shortest_edge(x);
        if (std::pow(l_max, 16) > 0x1p127 || std::pow(l_min, 16) < 0x1p-125) continue;
      }
      ++tested;
      const auto d = evaluate<Scalar>(symbolic, x);
      const auto e = exact(x);
      // Bound: the forward error of a plain evaluation, c kappa u with kappa the hinge's condition number
      // (tests/support/tolerance.hpp; at most about 130 on well-shaped hinges) and c = 8: every product is
      // rounded once with no compensation, and each output depends on a chain of about 20 of them
      // (measured worst error / kappa over these hinges: 5.5 double, 4.4 long double, 2.3 dd, 0.2 qd,
      // 5.0 float128 and bin128, 3.9 mpfr:113). float rounds the coordinates themselves to float first: a
      // perturbation of u |x|max per coordinate, relative u |x|max / l_min to the shortest edge, which the
      // same kappa amplifies (these hinges are offset by up to 100 with edges down to 1e-3).
      const double input = std::same_as<Scalar, float> ? 1 + max_coordinate(x) / shortest_edge(x) : 1;
      const double bound = 8 * test::condition_number(x) * input;
      const double err = std::max(test::normwise_units(d.hess, e.hess, u), test::normwise_units(d.grad, e.grad, u));
      worst = std::max(worst, err / test::condition_number(x) / input);
      ASSERT_LE(err, bound) << (symbolic ? "symbolic " : "autodiff ") << test::describe(x);
      const double t = to_double(e.angle.theta);
      ASSERT_LE(std::abs(to_double(d.theta) - t), (bound * u + 0x1p-53) * std::abs(t)) << test::describe(x);
    }
    std::cout << "[ measured ] " << (symbolic ? "symbolic " : "autodiff ") << test_name<Scalar>()
              << ": worst error / (kappa input) " << worst << " units (bound 8) on " << tested << " hinges\n";
    EXPECT_GE(tested, 50);
  }
}

TYPED_TEST(Baselines, OutputLevelsGiveTheSameValues) {
  using Scalar = TypeParam;
  for (const bool symbolic : {false, true}) {
    for (const auto& x : test::well_shaped_hinges(20, 22)) {
      const auto theta = evaluate<Scalar>(symbolic, x, Outputs::theta);
      const auto grad = evaluate<Scalar>(symbolic, x, Outputs::gradient);
      const auto all = evaluate<Scalar>(symbolic, x, Outputs::hessian);
      // autodiff computes theta by the same operations at every level (the value part of the dual
      // numbers), and the gradient by the same operations with and without the second-order part: bit
      // for bit. The generated code's levels are separate cse runs that may order operations
      // differently: within the accuracy bound above, checked through the reference test.
      if (!symbolic) {
        ASSERT_EQ(to_double(theta.theta), to_double(all.theta)) << test::describe(x);
        ASSERT_EQ(to_double(grad.theta), to_double(all.theta)) << test::describe(x);
      }
      for (int i = 0; i < 12; ++i) ASSERT_EQ(to_double(theta.grad[i]), 0.0);  // not computed: left zero
    }
  }
}

TYPED_TEST(Baselines, FarFromUnitSizeTheyGiveNumbersOrNaNAndNeverCrash) {
  using Scalar = TypeParam;
  // The baselines do not rescale: at 2^+-300 their intermediates (up to l^16) overflow or underflow in the
  // types with double's exponent range, and the results are NaN or infinite (what the study counts as
  // non-finite). They must not crash: QD's atan2 does on a NaN argument (common.hpp guards it), and what
  // the guard lets through lies in atan2's range.
  for (const auto& x : test::well_shaped_hinges(5, 26))
    for (int k : {-500, -300, 300, 500}) {
      std::array<double, 12> y;
      for (int i = 0; i < 12; ++i) y[i] = std::ldexp(x[i], k);
      for (const bool symbolic : {false, true}) {
        const double theta = to_double(evaluate<Scalar>(symbolic, y).theta);
        EXPECT_TRUE(std::isnan(theta) || std::abs(theta) <= to_double(pi_of<Scalar>())) << k << " " << theta;
      }
    }
}

TYPED_TEST(Baselines, DegenerateHingesAreInputErrors) {
  using Scalar = TypeParam;
  std::array<double, 12> x = test::flat_hinge();
  x[9] = x[3], x[10] = x[4], x[11] = x[5];  // x3 == x1: the lower triangle has zero area
  EXPECT_THROW(evaluate<Scalar>(false, x), InputError);
  EXPECT_THROW(evaluate<Scalar>(true, x), InputError);
  x = test::flat_hinge();
  x[4] = NAN;
  EXPECT_THROW(evaluate<Scalar>(false, x), InputError);
  EXPECT_THROW(evaluate<Scalar>(true, x), InputError);
}

TYPED_TEST(Baselines, FoldedFlatHingeHasThetaPlusPi) {
  using Scalar = TypeParam;
  // x3 = x0: the two triangles coincide, folded flat onto each other; the numerator is exactly zero
  // (both normals are opposite and parallel, their cross product rounds to zero or not: either way theta
  // is +-pi up to rounding, and an exact -pi is reported as +pi).
  std::array<double, 12> x = test::flat_hinge();
  x[9] = x[0], x[10] = x[1], x[11] = x[2];
  for (const bool symbolic : {false, true}) {
    const auto d = evaluate<Scalar>(symbolic, x, Outputs::theta);
    EXPECT_EQ(to_double(d.theta), to_double(pi_of<Scalar>())) << (symbolic ? "symbolic" : "autodiff");
  }
}

}  // namespace
}  // namespace hinge::baselines
