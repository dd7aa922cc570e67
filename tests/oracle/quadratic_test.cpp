// The certified isometric bending term (hinge/oracle/quadratic.hpp) against its definition and its proved
// properties (docs/quantities.md, "quadratic"; proofs/quadratic-bending.md).
#include "hinge/oracle/quadratic.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hinge/core/errors.hpp"
#include "hinge/oracle/conditioning.hpp"

namespace {

using hinge::oracle::certified_quadratic;
using X12 = std::array<double, 12>;
constexpr double u = 0x1p-53;

// A flat rest hinge in the plane z = 0 (x0 above the edge x1 -> x2, x3 below, an obtuse triangle included).
const X12 flat_rest{0.25, 1.0, 0.0, 0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 1.75, -0.75, 0.0};

// The definition in double (docs/quantities.md): K from the cotangents, psi = 3 k / A_bar |sum K_j x_j|^2.
struct Plain {
  double psi;
  std::array<double, 4> K;
  double c;
};
Plain plain(const X12& x, const X12& r, double k) {
  auto v = [&](const X12& p, int i) { return std::array<double, 3>{p[3 * i], p[3 * i + 1], p[3 * i + 2]}; };
  auto sub = [](std::array<double, 3> a, std::array<double, 3> b) {
    return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  auto dot = [](std::array<double, 3> a, std::array<double, 3> b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  auto cross_norm = [](std::array<double, 3> a, std::array<double, 3> b) {
    return std::hypot(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
  };
  const auto e0 = sub(v(r, 2), v(r, 1)), e1 = sub(v(r, 0), v(r, 2)), e2 = sub(v(r, 1), v(r, 0));
  const auto t1 = sub(v(r, 3), v(r, 2)), t2 = sub(v(r, 1), v(r, 3));
  const double N = cross_norm(e0, e1), Nt = cross_norm(e0, t1);
  const double cot1 = -dot(e0, e2) / N, cot2 = -dot(e0, e1) / N, cott1 = -dot(e0, t2) / Nt, cott2 = -dot(e0, t1) / Nt;
  Plain p;
  p.K = {-(cot1 + cot2), cot2 + cott2, cot1 + cott1, -(cott1 + cott2)};
  p.c = 3 * k / ((N + Nt) / 2);
  std::array<double, 3> s{};
  for (int j = 0; j < 4; ++j)
    for (int a = 0; a < 3; ++a) s[a] += p.K[j] * x[3 * j + a];
  p.psi = p.c * dot(s, s);
  return p;
}

// x0 turned about the hinge edge (the x axis) by `angle`: an isometric bend of the flat rest hinge.
X12 folded(double angle) {
  X12 x = flat_rest;
  const double y = x[1];
  x[1] = y * std::cos(angle);
  x[2] = y * std::sin(angle);
  return x;
}

TEST(Quadratic, AtAFlatRestHingeTheEnergyAndForceAreExactlyZeroAndTheHessianIs2cKKt) {
  const auto q = certified_quadratic(flat_rest, flat_rest, 1.0);
  EXPECT_EQ(q.energy, 0.0);
  for (const double g : q.grad) EXPECT_EQ(g, 0.0);
  EXPECT_TRUE(q.uncertified.empty());
  const Plain p = plain(flat_rest, flat_rest, 1.0);
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      const double want = i % 3 == j % 3 ? 2 * p.c * p.K[i / 3] * p.K[j / 3] : 0.0;
      // The plain evaluation: a few roundings in each cotangent, sum and product (about 16 u relative).
      EXPECT_NEAR(q.hess[12 * i + j], want, 16 * u * std::fabs(want)) << i << ", " << j;
      if (i % 3 != j % 3) {
        EXPECT_EQ(q.hess[12 * i + j], 0.0);
      }
    }
}

TEST(Quadratic, TheCertifiedEnergyIsTheDefinitionsToWithinItsRounding) {
  const X12 x{0.3, 0.9, 0.2, 0.1, -0.05, 0.02, 1.4, 0.1, -0.1, 1.8, -0.7, 0.3};
  const auto q = certified_quadratic(x, flat_rest, 2.5);
  const Plain p = plain(x, flat_rest, 2.5);
  EXPECT_NEAR(q.energy, p.psi, 64 * u * p.psi);  // the plain sum over x_j (not x_j - x1): a few tens of u here
}

TEST(Quadratic, OnAnIsometricBendItIsFourWillmoreExactlyAsProved) {
  for (const double angle : {1e-3, 0.5, 2.0, 3.0}) {
    const X12 x = folded(angle);
    const auto q = certified_quadratic(x, flat_rest, 1.0);
    const double theta = hinge::oracle::certified_theta_derivatives(x).theta;
    const double a = 3 * 1.5 * 1.5 / (0.75 + 0.5625);  // 3 |e_bar|^2 / A_bar: triangle areas 0.75 and 0.5625
    const double want = 4 * a * std::sin(theta / 2) * std::sin(theta / 2);
    // x is the fold rounded to doubles (isometric to within u): relative error a few u over sin^2(theta/2).
    EXPECT_NEAR(q.energy, want, 1e3 * u * want / std::min(1.0, angle)) << angle;
  }
}

TEST(Quadratic, ExactRigidMotionsLeaveTheEnergyAndTurnTheGradient) {
  const X12 x{0.3, 0.9, 0.2, 0.1, -0.05, 0.02, 1.4, 0.1, -0.1, 1.8, -0.7, 0.3};
  X12 turned{}, moved{};
  for (int j = 0; j < 4; ++j) {  // a quarter turn about z, (x, y, z) -> (-y, x, z); a translation by 2^-2, 1, 4
    turned[3 * j] = -x[3 * j + 1], turned[3 * j + 1] = x[3 * j], turned[3 * j + 2] = x[3 * j + 2];
    moved[3 * j] = x[3 * j] + 0.25, moved[3 * j + 1] = x[3 * j + 1] + 1, moved[3 * j + 2] = x[3 * j + 2] + 4;
  }
  const auto q = certified_quadratic(x, flat_rest, 1.0), qt = certified_quadratic(turned, flat_rest, 1.0);
  EXPECT_EQ(qt.energy, q.energy);  // the same exact value: |Q s| = |s|
  for (int j = 0; j < 4; ++j) {
    EXPECT_EQ(qt.grad[3 * j], -q.grad[3 * j + 1]);
    EXPECT_EQ(qt.grad[3 * j + 1], q.grad[3 * j]);
  }
  // The translation rounds x (x + t is not always a double): equal to within the inputs' rounding.
  EXPECT_NEAR(certified_quadratic(moved, flat_rest, 1.0).energy, q.energy, 64 * u * q.energy);
}

TEST(Quadratic, TheNetForceIsZeroAsTheWeightsSumToZero) {
  const X12 x{0.3, 0.9, 0.2, 0.1, -0.05, 0.02, 1.4, 0.1, -0.1, 1.8, -0.7, 0.3};
  const auto q = certified_quadratic(x, flat_rest, 1.0);
  double norm = 0;
  for (const double g : q.grad) norm = std::max(norm, std::fabs(g));
  for (int a = 0; a < 3; ++a) {
    const double net = q.grad[a] + q.grad[3 + a] + q.grad[6 + a] + q.grad[9 + a];
    EXPECT_LE(std::fabs(net), 4 * u * norm);  // four correctly rounded terms of an exact zero sum
  }
}

TEST(Quadratic, ConditioningIsFiniteAndSmallOnAWellShapedHinge) {
  const X12 x{0.3, 0.9, 0.2, 0.1, -0.05, 0.02, 1.4, 0.1, -0.1, 1.8, -0.7, 0.3};
  const auto q = certified_quadratic(x, flat_rest, 1.0);
  const auto k = hinge::oracle::quadratic_conditioning(x, flat_rest, 1.0, q.energy, q.grad, q.hess);
  for (int g = 0; g < 3; ++g) {
    EXPECT_TRUE(std::isfinite(k.kappa[g])) << g;
    EXPECT_GT(k.kappa[g], 0.1) << g;
    EXPECT_LT(k.kappa[g], 1e3) << g;  // a well-shaped hinge: derivatives of order one over its size
  }
}

TEST(Quadratic, ADegenerateRestTriangleIsAnInputError) {
  X12 r = flat_rest;
  r[0] = 0.75, r[1] = 0;  // x0 on the hinge edge
  EXPECT_THROW(certified_quadratic(flat_rest, r, 1.0), hinge::InputError);
}

}  // namespace
