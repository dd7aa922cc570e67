// The bending energies of energy.hpp: psi' and psi'' against finite differences of psi for every model,
// the rest state of Algorithm 1 (eq. (11) and a = 3|e|^2/A), and the errors where psi is infinite.
#include <gtest/gtest.h>

#include <numbers>

#include "hinge/core/energy.hpp"
#include "hinge/reference/evaluate.hpp"
#include "hinge/reference/hinge_energy.hpp"
#include "support/hinges.hpp"

namespace hinge::reference {
namespace {

using Real = mpfr;

BendAngle<Real> angle(const Real& theta) { return {theta, tan(theta / 2), false}; }

HingeCoefficients<Real> coefficients() {
  HingeCoefficients<Real> c;
  c.k = Real(0.75);
  c.a = Real(2.5);
  c.theta_bar = Real(0.4);
  c.phi_bar = 2 * tan(c.theta_bar / 2);
  c.k_d_over_dt = Real(3);
  c.phi_hat = 2 * tan(Real(-0.2) / 2);
  return c;
}

TEST(Energy, DerivativesMatchFiniteDifferencesForEveryModel) {
  set_mpfr_bits(256);
  const Real h("1e-20");
  for (Model model : {Model::shells, Model::tan, Model::willmore, Model::bridson, Model::viscoelastic})
    for (double t : {-2.5, -0.3, 0.0, 0.4, 1.7, 3.0}) {
      const Real theta = t;
      const auto c = coefficients();
      const Psi<Real> p = psi(model, c, angle(theta));
      const Psi<Real> plus = psi(model, c, angle(theta + h)), minus = psi(model, c, angle(theta - h));
      // Central differences at h = 1e-20 in 256 bits: truncation ~h^2 = 1e-40, rounding ~1e-77/h.
      const Real d1 = (plus.value - minus.value) / (2 * h), d2 = (plus.d1 - minus.d1) / (2 * h);
      EXPECT_LT(to_double(abs(d1 - p.d1)), 1e-30 * (1 + to_double(abs(p.d1)))) << model_name(model) << " " << t;
      EXPECT_LT(to_double(abs(d2 - p.d2)), 1e-30 * (1 + to_double(abs(p.d2)))) << model_name(model) << " " << t;
    }
}

TEST(Energy, RestAngleIsAMinimumOfShellsAndTan) {
  for (Model model : {Model::shells, Model::tan}) {
    const auto c = coefficients();
    const Psi<Real> p = psi(model, c, angle(c.theta_bar));
    EXPECT_EQ(to_double(p.value), 0.0);
    EXPECT_EQ(to_double(p.d1), 0.0);
    EXPECT_GT(to_double(p.d2), 0.0);
  }
  // Bridson's force vanishes at rest too: psi' = k a (sin(theta/2) - sin(theta_bar/2)).
  const auto c = coefficients();
  EXPECT_LT(to_double(abs(psi(Model::bridson, c, angle(c.theta_bar)).d1)), 1e-70);
}

TEST(Energy, TanEnergyIsAnErrorOnTheBranchCut) {
  const std::array<double, 12> folded = {0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.25, 2, 0};
  const auto d = theta_derivatives<double>(folded);
  HingeCoefficients<double> c;
  c.k = 1;
  c.a = 1;
  EXPECT_THROW(psi(Model::tan, c, d.angle), DomainError);
  EXPECT_THROW(psi(Model::viscoelastic, c, d.angle), DomainError);
  EXPECT_NO_THROW(psi(Model::shells, c, d.angle));  // finite there: theta = pi is defined
}

TEST(Energy, BendingStiffnessIsEquationEleven) {
  // Y = 24, h = 0.5, nu = 0.5: k = 24 * 0.125 / (24 * 0.75) = 1/6.
  EXPECT_DOUBLE_EQ(bending_stiffness(24.0, 0.5, 0.5), 1.0 / 6.0);
}

TEST(Energy, RestCoefficientsOfTheCheckHinge) {
  // Check hinge of docs/contract.md: |e0| = 1, both triangles of area 1/2: a = 3 * 1 / 1 = 3, theta_bar = 0.
  const PreparedHinge<double> p = prepare_hinge<double>(test::flat_hinge());
  const auto c = rest_coefficients(Model::tan, p.stencil, bend_angle(p.stencil, p.sign), 2.0);
  EXPECT_EQ(c.a, 3.0);
  EXPECT_EQ(c.theta_bar, 0.0);
  EXPECT_EQ(c.phi_bar, 0.0);
  EXPECT_EQ(c.k, 2.0);
}

TEST(Energy, ModelNamesRoundTrip) {
  for (Model model : {Model::shells, Model::tan, Model::willmore, Model::bridson, Model::viscoelastic})
    EXPECT_EQ(parse_model(model_name(model)), model);
  EXPECT_THROW(parse_model("cubic"), std::invalid_argument);
}

}  // namespace
}  // namespace hinge::reference
