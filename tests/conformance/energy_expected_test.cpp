// What a bending term must give on an energy case (hinge/conformance/energy_expected.hpp): at rest and at the
// rest angle the certified force is exactly zero (shells, tan, bridson) and so is the energy (shells, tan);
// where the energy is exactly zero the tolerance is the contract's bound c f''(theta_bar) (16 u (s_X +
// s_R))^2 / 2, no more and no less; the Gauss-Newton Hessian is what the oracle certifies as such.
#include <gtest/gtest.h>

#include <cmath>

#include "hinge/conformance/energy_expected.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {
namespace {

std::vector<EnergyCase> cases_of(const std::string& kind) {
  std::vector<EnergyCase> out;
  for (const EnergyCase& c : energy_inputs(3).cases)
    if (c.category.substr(c.category.find('/') + 1) == kind) out.push_back(c);
  return out;
}

TEST(EnergyExpected, AtRestAndAtTheRestAngleTheForceIsExactlyZero) {
  for (const char* kind : {"at-rest", "rest-angle"})
    for (const EnergyCase& c : cases_of(kind))
      for (Model model : {Model::shells, Model::tan, Model::bridson}) {
        EnergyProblem p;
        p.model = model;
        try {
          const Expected e = energy_expected(c, p, false);
          for (double g : e.values.grad) EXPECT_EQ(g, 0.0) << c.id << " " << model_name(model);
          if (model != Model::bridson) {
            EXPECT_EQ(e.values.theta, 0.0) << c.id << " " << model_name(model);
          }
        } catch (const DomainError&) {  // tan on a folded hinge
        }
      }
}

TEST(EnergyExpected, AZeroEnergyPassesExactlyUpToTheContractsBound) {
  int checked = 0;
  for (const EnergyCase& c : cases_of("at-rest")) {
    if (c.category.rfind("scales/", 0) == 0) continue;  // this test's own formula below over- or underflows there
    EnergyProblem p;
    p.model = Model::shells;
    const Expected e = energy_expected(c, p);
    ASSERT_EQ(e.values.theta, 0.0) << c.id;
    // The bound, recomputed: shells' psi'' = 2 k a.
    const oracle::CertifiedTheta t = oracle::certified_theta_derivatives(c.x);
    const double s = 2 * e.conditioning.length * oracle::scaled_norm(t.grad.data(), 12);  // X == R: s_X = s_R
    double e0 = 0, area = 0;
    const auto d = [&](int a, int b, int k) { return c.x[3 * a + k] - c.x[3 * b + k]; };
    for (int k = 0; k < 3; ++k) e0 += d(2, 1, k) * d(2, 1, k);
    for (const auto& [o, a, b] : {std::array{0, 1, 2}, std::array{3, 2, 1}}) {
      const double u[3] = {d(a, o, 0), d(a, o, 1), d(a, o, 2)}, v[3] = {d(b, o, 0), d(b, o, 1), d(b, o, 2)};
      area += std::sqrt(std::pow(u[1] * v[2] - u[2] * v[1], 2) + std::pow(u[2] * v[0] - u[0] * v[2], 2) +
                        std::pow(u[0] * v[1] - u[1] * v[0], 2)) /
              2;
    }
    const double bound = 2 * (3 * e0 / area) * std::pow(16 * 0x1p-53 * s, 2) / 2;
    CandidateResult r;
    r.status = CandidateResult::Status::ok;
    r.grad = e.values.grad;
    r.hess = e.values.hess;
    r.theta = 0.999 * bound;  // within: 0.1% below (the bound itself is computed in double twice, 1e-15 apart)
    EXPECT_TRUE(compare(e, r, {}).pass) << c.id;
    r.theta = 1.001 * bound;
    EXPECT_FALSE(compare(e, r, {}).pass) << c.id;
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

TEST(EnergyExpected, TheGaussNewtonHessianIsRankOneAndDiffersFromTheExactOneAwayFromRest) {
  for (const EnergyCase& c : cases_of("obtuse")) {
    EnergyProblem p;
    p.model = Model::shells;
    const Expected exact = energy_expected(c, p, false);
    p.hessian = HessianKind::gauss_newton;
    const Expected gn = energy_expected(c, p, false);
    EXPECT_EQ(gn.values.theta, exact.values.theta) << c.id;
    EXPECT_EQ(gn.values.grad, exact.values.grad) << c.id;
    EXPECT_NE(gn.values.hess, exact.values.hess) << c.id;
    // rank one: every 2 x 2 minor of c f'' g g^T vanishes, to the rounding of its entries (8 ulps relative)
    const auto H = [&](int i, int j) { return gn.values.hess[static_cast<std::size_t>(12 * i + j)]; };
    for (int i = 0; i < 12; i += 5)
      for (int j = 1; j < 12; j += 5) {
        const double minor = H(i, i) * H(j, j) - H(i, j) * H(j, i);
        EXPECT_LE(std::fabs(minor), 8 * 0x1p-53 * std::fabs(H(i, i) * H(j, j)) + 1e-300) << c.id;
      }
  }
}

TEST(EnergyExpected, TheZeroEnergyBoundDoesNotChangeWithTheScaleOfTheHinge) {
  // a = 3 |e_bar|^2 / A_bar and the theta scales are scale-free: so is the bound, from 2^-500 to 2^500.
  for (const EnergyCase& c : cases_of("at-rest")) {
    if (c.category.rfind("scales/", 0) != 0) continue;
    EnergyProblem p;
    p.model = Model::shells;
    const Expected e = energy_expected(c, p);
    const double tolerance = Policy{}.base + Policy{}.c;
    const double bound = e.conditioning.scale[0] * tolerance * 0x1p-53;
    EXPECT_TRUE(std::isfinite(bound) && bound > 0 && bound < 1e-20) << c.id << " " << bound;
  }
}

}  // namespace
}  // namespace hinge::conformance
