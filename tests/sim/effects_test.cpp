// The effects' potentials: gradients and Hessians agree with finite differences at large bends (near-folded
// hinges included); a rigid motion costs no stretching or bending energy; a curved rest shape (non-zero and
// obtuse rest angles) is an equilibrium; the projected bending Hessian is positive semidefinite; the
// membrane under uniaxial stress contracts by nu epsilon and carries Y h W epsilon (plane stress).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

#include "sim_support.hpp"

namespace hinge::sim {
namespace {

using test::u;

// A 4 x 3 cloth bent hard: a fold along x = 0 of nearly 180 degrees (near-folded hinges) and a twist.
Mesh bent(const Mesh& flat, double fold) {
  Mesh m = flat;
  for (auto& p : m.vertices) {
    const double x = p[0], y = p[1];
    if (x > 0) p = {x * std::cos(fold), y + 0.05 * x * y, x * std::sin(fold) + 0.02 * y * y};
    else p = {x, y, 0.03 * x * y};
  }
  return m;
}

Scene everything(Model energy) {
  Scene s = test::cloth(4, 3, 0.3, 0.2);
  s.gravity = Gravity{{0.5, -1, -9.81}};
  s.stretching = Stretching{};
  s.bending = Bending{energy, 1e-3};
  s.load = Load{{1, 5}, {0.3, 0.2, -1}};
  s.solve.hessian = HessianTreatment::exact;
  return s;
}

// Central differences with step h = u^(1/3) L (L = 0.3, the cloth's size) have truncation error
// h^2 |D^3 f| / 6 and rounding error u |f| / h; with |D^3 f| L^3 / |Df| and |f| / (L |Df|) below C, both
// are about C u^(2/3) = 4e-11 C relative to the derivative. The bent cloth's C stays below ~1e4 (the fold's
// curvature and tan's growth near pi): bound 1e-6, normwise, for each effect on its own.
constexpr double kFiniteDifferenceTolerance = 1e-6;

// Each effect alone: its gradient against central differences of its energy, and (if `hessian`) its Hessian
// against central differences of its gradient.
void expect_derivatives_match_finite_differences(const Scene& scene, const Mesh& state, bool hessian = true,
                                                 const Mesh* step_start = nullptr, double dt = 0) {
  test::Effects fx(scene, dt);
  const Eigen::VectorXd x = test::coordinates(state);
  for (auto& effect : fx.all) {
    SCOPED_TRACE(std::string(effect->name()));
    if (step_start) {
      effect->begin_step(test::coordinates(*step_start), Eigen::VectorXd::Zero(x.size()));
    }
    auto alone = [&](const Eigen::VectorXd& at, unsigned request) {
      Evaluation e;
      e.request = request;
      e.gradient.setZero(at.size());
      e.hessian.assign(static_cast<std::size_t>(fx.sparsity.nonzeros()), 0.0);
      effect->add(at, e);
      return e;
    };
    const Evaluation at = alone(x, 7);
    if (at.gradient.isZero(0.0)) continue;  // pins
    const Eigen::MatrixXd H = fx.dense(at);
    const double h = std::cbrt(u) * 0.3;
    Eigen::VectorXd g_fd(x.size());
    Eigen::MatrixXd H_fd(x.size(), x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      Eigen::VectorXd plus = x, minus = x;
      plus[i] += h, minus[i] -= h;
      const Evaluation ep = alone(plus, 3), em = alone(minus, 3);
      g_fd[i] = (ep.energy - em.energy) / (2 * h);
      H_fd.col(i) = (ep.gradient - em.gradient) / (2 * h);
    }
    EXPECT_LE((g_fd - at.gradient).norm(), kFiniteDifferenceTolerance * at.gradient.norm());
    if (hessian && H.norm() > 0) {
      EXPECT_LE((H_fd - H).norm(), kFiniteDifferenceTolerance * H.norm());
    }
  }
}

TEST(Effects, ExactGradientAndHessianMatchFiniteDifferencesAtLargeBends) {
  for (auto energy : {Model::tan, Model::shells, Model::willmore, Model::bridson})
    for (double fold : {0.3, 2.0, 3.0}) {  // 3.0 rad: near-folded (tan(theta/2) ~ 14)
      SCOPED_TRACE(std::string(model_name(energy)) + " fold " + std::to_string(fold));
      Scene s = everything(energy);
      expect_derivatives_match_finite_differences(s, bent(s.mesh, fold));
    }
}

TEST(Effects, ProjectedAndGaussNewtonKeepTheExactGradient) {
  for (auto treatment : {HessianTreatment::projected, HessianTreatment::gauss_newton}) {
    Scene s = everything(Model::tan);
    s.solve.hessian = treatment;
    expect_derivatives_match_finite_differences(s, bent(s.mesh, 2.0), false);
  }
}

TEST(Effects, DampingDerivativesMatchFiniteDifferences) {
  // The mass part and the paper's viscoelastic bending (section 5), from a step that started elsewhere.
  Scene s = everything(Model::tan);
  s.damping = Damping{3.0, 0.02};
  s.solve.mode = Mode::dynamic, s.solve.dt = 0.01, s.solve.steps = 1;
  for (auto treatment : {HessianTreatment::exact, HessianTreatment::projected}) {
    s.solve.hessian = treatment;
    const Mesh start = bent(s.mesh, 1.6);
    expect_derivatives_match_finite_differences(s, bent(s.mesh, 2.0), treatment == HessianTreatment::exact, &start,
                                                0.01);
  }
}

TEST(Effects, SphereBarrierDerivativesMatchFiniteDifferencesAndItsProjectedHessianIsPositiveSemidefinite) {
  Scene s = test::cloth(3, 3, 0.02, 0.02, 0.5);
  s.sphere = Sphere{{0, 0, 0}, 0.497};  // every vertex within d_hat = r / 100 of the surface
  test::Effects fx(s);
  const Eigen::VectorXd x = test::coordinates(s.mesh);
  const Evaluation at = fx.evaluate(x);
  ASSERT_GT(at.energy, 0);
  const double h = std::cbrt(u) * 1e-3;  // u^(1/3) times the gap's scale (the barrier's length scale)
  Eigen::MatrixXd H_fd(x.size(), x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    Eigen::VectorXd plus = x, minus = x;
    plus[i] += h, minus[i] -= h;
    const Evaluation ep = fx.evaluate(plus, 3), em = fx.evaluate(minus, 3);
    EXPECT_NEAR((ep.energy - em.energy) / (2 * h), at.gradient[i], kFiniteDifferenceTolerance * at.gradient.norm())
        << i;
    H_fd.col(i) = (ep.gradient - em.gradient) / (2 * h);
  }
  // The true Hessian kappa (b'' n n^T + b' (I - n n^T) / |x - c|), in the scene's treatment and the dump's.
  for (auto treatment : {Treatment::scene, Treatment::exact}) {
    const Eigen::MatrixXd H = fx.dense(fx.evaluate(x, 7, treatment));
    EXPECT_LE((H_fd - H).norm(), kFiniteDifferenceTolerance * H.norm());
  }
  // The projected rung keeps kappa b'' n n^T per vertex: positive semidefinite (to the eigensolver's rounding).
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(fx.dense(fx.evaluate(x, 7, Treatment::projected)));
  EXPECT_GE(eig.eigenvalues().minCoeff(), -64 * u * eig.eigenvalues().maxCoeff());
}

TEST(Effects, SphereStopsEveryStepShortOfItsSurface) {
  Scene s = test::cloth(2, 2, 0.1, 0.1, 0.3);
  s.sphere = Sphere{{0, 0, 0}, 0.25};
  test::Effects fx(s);
  const Eigen::VectorXd x = test::coordinates(s.mesh);
  Eigen::VectorXd down = Eigen::VectorXd::Zero(x.size());
  for (Eigen::Index v = 0; v < 4; ++v) down[3 * v + 2] = -1;  // straight down by 1 m: through the sphere
  const double alpha = fx.all[0]->max_step(x, down);
  // Every vertex (all four alike) reaches the surface at z = sqrt(r^2 - 2 (0.05)^2): the step stops at 0.8
  // of that way (to rounding: a few operations on numbers of size 1).
  const double z_surface = std::sqrt(0.25 * 0.25 - 2 * 0.05 * 0.05);
  EXPECT_NEAR(alpha, 0.8 * (0.3 - z_surface), 8 * u);
  EXPECT_EQ(fx.all[0]->max_step(x, -down), 1.0);  // moving away: no limit
}

TEST(Effects, ARigidMotionCostsNoStretchingOrBendingEnergy) {
  for (auto energy : {Model::tan, Model::shells}) {
    Scene s = test::cloth(5, 4, 0.4, 0.3);
    s.rest = bent(s.mesh, 1.0);  // a curved rest shape
    s.mesh = s.rest;
    s.stretching = Stretching{};
    s.bending = Bending{energy, 1e-3};
    test::Effects fx(s);
    const Eigen::AngleAxisd rotation(0.7, Eigen::Vector3d(1, 2, 3).normalized());
    Mesh moved = s.rest;
    for (auto& p : moved.vertices) {
      const Eigen::Vector3d q = rotation * Eigen::Vector3d(p.data()) + Eigen::Vector3d(3, -2, 1);
      p = {q[0], q[1], q[2]};
    }
    // Reference scale: the same cloth stretched by 1e-3 (strain energy ~ Y h A 1e-6).
    Mesh stretched = s.rest;
    for (auto& p : stretched.vertices) p = {p[0] * 1.001, p[1] * 1.001, p[2] * 1.001};
    const Evaluation rigid = fx.evaluate(test::coordinates(moved), 3);
    const Evaluation strained = fx.evaluate(test::coordinates(stretched), 3);
    // The rotated coordinates carry relative errors ~u, so strains ~u: energy ~(u / 1e-3)^2 of the strained
    // one's, gradient ~u / 1e-3 of its; bounds with a factor 1e3 for the rounding of rotation and strain.
    EXPECT_LE(rigid.energy, 1e3 * (u / 1e-3) * (u / 1e-3) * strained.energy);
    EXPECT_LE(rigid.gradient.norm(), 1e3 * (u / 1e-3) * strained.gradient.norm());
  }
}

TEST(Effects, ACurvedRestShapeWithObtuseAnglesIsAnEquilibrium) {
  for (auto energy : {Model::tan, Model::shells, Model::bridson}) {
    Scene s = test::cloth(5, 4, 0.4, 0.3);
    s.rest = bent(s.mesh, 2.2);  // a fold of 2.2 rad: rest angles above pi/2
    s.mesh = s.rest;
    s.stretching = Stretching{};
    s.bending = Bending{energy, 1e-3};
    test::Effects fx(s);
    const Evaluation at_rest = fx.evaluate(test::coordinates(s.rest), 3);
    Mesh nudged = s.rest;
    nudged.vertices[7][2] += 1e-3;
    const Evaluation off = fx.evaluate(test::coordinates(nudged), 3);
    // The force at rest is rounding: ~u relative to the forces of a 1e-3 displacement over ~1e-3 ... bound
    // 1e3 u / 1e-3 of them.
    EXPECT_LE(at_rest.gradient.norm(), 1e3 * u / 1e-3 * off.gradient.norm()) << model_name(energy);
  }
}

TEST(Effects, ARestHingeFoldedFlatIsAnInputErrorNamingItsEdge) {
  // One rest triangle turned over onto its neighbour (theta_bar = pi): eq. (10) fails there, for every energy.
  for (auto energy : {Model::shells, Model::tan}) {
    Scene s = test::cloth(3, 3, 0.2, 0.2);
    s.rest.vertices[3] = {-0.02, -0.06, 0};  // vertex 3 across the diagonal 0-4: face (0, 4, 3) turned over
    s.bending = Bending{energy, 1e-3};
    try {
      test::Effects fx(s);
      ADD_FAILURE() << "no error for " << model_name(energy);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("test-scene.json: effects.bending: the rest shape: "), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("is folded flat (theta_bar = pi"), std::string::npos) << e.what();
    }
  }
}

TEST(Effects, ProjectedBendingHessianIsPositiveSemidefinite) {
  Scene s = test::cloth(4, 3, 0.3, 0.2);
  s.bending = Bending{Model::tan, 1e-3};
  s.solve.hessian = HessianTreatment::projected;
  test::Effects fx(s);
  const Evaluation at = fx.evaluate(test::coordinates(bent(s.mesh, 2.5)));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(fx.dense(at));
  // Each hinge's 12 x 12 projected exactly up to the eigensolver's backward error (~u times its norm).
  EXPECT_GE(eig.eigenvalues().minCoeff(), -64 * u * eig.eigenvalues().maxCoeff());
  s.solve.hessian = HessianTreatment::exact;
  test::Effects exact(s);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> e2(exact.dense(exact.evaluate(test::coordinates(bent(s.mesh, 2.5)))));
  EXPECT_LT(e2.eigenvalues().minCoeff(), -1e-3 * e2.eigenvalues().maxCoeff());  // the exact one is not
}

TEST(Effects, OtherMethodsGiveTheFastKernelsResultsToRounding) {
  Scene s = everything(Model::tan);
  const Mesh state = bent(s.mesh, 2.0);
  test::Effects fast(s);
  const Evaluation f = fast.evaluate(test::coordinates(state));
  for (const char* method : {"reference", "autodiff"}) {
    s.bending->method = parse_method(method);
    test::Effects other(s);
    const Evaluation o = other.evaluate(test::coordinates(state));
    // Each method within a few units of 2^-53 of the exact bending derivatives (docs/accuracy); the sums
    // over 17 hinges and the other effects' identical parts: 1e3 u normwise.
    EXPECT_LE(std::abs(o.energy - f.energy), 1e3 * u * std::abs(f.energy)) << method;
    EXPECT_LE((o.gradient - f.gradient).norm(), 1e3 * u * f.gradient.norm()) << method;
    EXPECT_LE((other.dense(o) - fast.dense(f)).norm(), 1e3 * u * fast.dense(f).norm()) << method;
  }
}

// A sheet of width W (along y) stretched along x by a small strain epsilon, free to contract along y:
// plane-stress elasticity says its lateral strain is -nu epsilon and the force on its stretched edge Y h W
// epsilon (the 3D Lame lambda in place of the plane-stress one would give -nu / (1 - nu) epsilon and more
// force). The membrane's uniform strain state: the lateral strain that leaves the top edge without force.
TEST(Effects, TheMembraneUnderUniaxialStressContractsByNuEpsilonAndCarriesYhWEpsilon) {
  Scene s = test::cloth(5, 4, 0.4, 0.3);
  s.material.poisson = 0.3;
  s.stretching = Stretching{};
  test::Effects fx(s);
  const double epsilon = 1e-7, W = 0.3, Y = s.material.young, h = s.material.thickness, nu = s.material.poisson;
  auto forces = [&](double lateral) {  // the gradient at x = diag(1 + epsilon, 1 + lateral, 1) X
    Eigen::VectorXd x = test::coordinates(s.mesh);
    for (Eigen::Index v = 0; v < x.size() / 3; ++v) x[3 * v] *= 1 + epsilon, x[3 * v + 1] *= 1 + lateral;
    return fx.evaluate(x, 2).gradient;
  };
  auto edge_sum = [](const Eigen::VectorXd& g, int c, auto&& on_edge) {
    double sum = 0;
    for (Index v = 0; v < 20; ++v)
      if (on_edge(v % 5, v / 5)) sum += g[3 * v + c];
    return sum;
  };
  auto top = [](int, int j) { return j == 3; };
  auto right = [](int i, int) { return i == 4; };
  // The top edge's y force is affine in the lateral strain to O(epsilon^2): its root from two evaluations.
  const double f0 = edge_sum(forces(0), 1, top), f1 = edge_sum(forces(-epsilon), 1, top);
  const double lateral = -epsilon * f0 / (f0 - f1);
  // Tolerance 1e-6 relative: the strain's nonlinearity is O(epsilon) = 1e-7 relative, and forming the Green
  // strain F^T F - I at strain 1e-7 cancels to u / epsilon ~ 1e-9 relative.
  EXPECT_NEAR(lateral / epsilon, -nu, 1e-6);
  EXPECT_NEAR(edge_sum(forces(lateral), 0, right) / (Y * h * W * epsilon), 1.0, 1e-6);
}

}  // namespace
}  // namespace hinge::sim
