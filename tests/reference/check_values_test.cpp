// The check values and sign conventions of docs/contract.md, and the exact handling of degenerate and
// folded hinges (reference/include/hinge/reference/evaluate.hpp).
#include <gtest/gtest.h>

#include <numbers>

#include "hinge/core/errors.hpp"
#include "hinge/reference/evaluate.hpp"
#include "support/hinges.hpp"

namespace hinge::reference {
namespace {

TEST(CheckValues, FlatHingeHasZeroAngleAndUnitNormals) {
  const PreparedHinge<double> p = prepare_hinge<double>(test::flat_hinge());
  EXPECT_EQ(bend_angle(p.stencil, p.sign).theta, 0.0);
  EXPECT_EQ(p.stencil.upper.n, Vec3<double>(0, 0, 1));
  EXPECT_EQ(p.stencil.lower.n, Vec3<double>(0, 0, 1));
}

TEST(CheckValues, GradientAtApexIsMinusNormalOverAltitude) {  // eq. (4): d theta / d x0 = -n / h0 = (0,0,-1)
  const ThetaDerivatives<double> d = theta_derivatives<double>(test::flat_hinge());
  EXPECT_EQ(d.grad.segment<3>(0), Vec3<double>(0, 0, -1));
  EXPECT_EQ(d.grad.segment<3>(9), Vec3<double>(0, 0, -1));  // the mirror image: -n~ / h~0
}

TEST(CheckValues, LiftingApexAlongNormalMakesThetaNegative) {
  for (double lift : {1e-9, 0.25, 3.0}) {
    auto x = test::flat_hinge();
    x[2] = lift;  // x0 along +n = +z
    EXPECT_LT(theta_derivatives<double>(x).angle.theta, 0) << "lift " << lift;
    x[2] = -lift;
    EXPECT_GT(theta_derivatives<double>(x).angle.theta, 0) << "lift " << -lift;
  }
}

TEST(CheckValues, HingeFoldedOntoItselfHasThetaPlusPiInEveryType) {
  // x3 on x0's side of the hinge line, in the same plane: numerator exactly zero, denominator negative.
  const std::array<double, 12> folded = {0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.25, 2, 0};
  EXPECT_EQ(theta_derivatives<double>(folded).angle.theta, std::numbers::pi);
  EXPECT_TRUE(theta_derivatives<double>(folded).angle.on_branch_cut);
  EXPECT_EQ(theta_derivatives<float>(folded).angle.theta, std::numbers::pi_v<float>);
  EXPECT_GT(theta_derivatives<bin128>(folded).angle.theta, 3);
  // Far from the origin the same hinge still folds exactly (subtraction first, exact sign).
  std::array<double, 12> far = folded;
  for (double& c : far) c += 1e9;
  EXPECT_EQ(theta_derivatives<double>(far).angle.theta, std::numbers::pi);
}

TEST(CheckValues, NearlyFoldedHingeKeepsItsBranch) {
  // x3 a hair below the plane of T on x0's side: theta just below +pi or just above -pi, by the exact sign.
  std::array<double, 12> x = {0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.25, 2, 1e-300};
  const double up = theta_derivatives<double>(x).angle.theta;
  x[11] = -1e-300;
  const double down = theta_derivatives<double>(x).angle.theta;
  EXPECT_GT(std::abs(up), 3.14);
  EXPECT_GT(std::abs(down), 3.14);
  EXPECT_NE(std::signbit(up), std::signbit(down));
}

TEST(Degenerate, ZeroLengthHingeEdgeIsRejected) {
  auto x = test::flat_hinge();
  x[6] = 0;  // x2 = x1
  EXPECT_THROW(theta_derivatives<double>(x), InputError);
}

TEST(Degenerate, CollinearTriangleIsRejectedExactlyEvenFarFromOrigin) {
  // x0 on the line through x1 and x2, 1e15 away from the origin: exact, not a rounding accident.
  std::array<double, 12> x = {3, 0, 0, 0, 0, 0, 1, 0, 0, 0.5, -1, 0};
  for (double& c : x) c += 1e15;
  try {
    theta_derivatives<double>(x);
    FAIL() << "collinear upper triangle accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("upper triangle"), std::string::npos) << e.what();
  }
  x[2] += 1;  // lift x0 by one unit: a valid hinge again
  EXPECT_NO_THROW(theta_derivatives<double>(x));
}

TEST(Degenerate, NonFiniteCoordinateIsRejected) {
  auto x = test::flat_hinge();
  x[4] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(theta_derivatives<double>(x), InputError);
}

TEST(Degenerate, TinyAndHugeHingesEvaluateWithoutOverflow) {
  // Scaled by 2^-1000 and 2^1000 (exact): theta is the same, grad scales as 1/s (power-of-two scaling
  // in evaluate.hpp keeps every intermediate in range).
  const auto base = theta_derivatives<double>({0.5, 1, 0.25, 0, 0, 0, 1, 0, 0, 0.25, -1, 0.5});
  for (int p : {-1000, 1000}) {
    std::array<double, 12> x = {0.5, 1, 0.25, 0, 0, 0, 1, 0, 0, 0.25, -1, 0.5};
    for (double& c : x) c = std::ldexp(c, p);
    const auto d = theta_derivatives<double>(x, false);
    EXPECT_EQ(d.angle.theta, base.angle.theta);
    for (int i = 0; i < 12; ++i) EXPECT_EQ(d.grad[i], std::ldexp(base.grad[i], -p));
  }
}

}  // namespace
}  // namespace hinge::reference
