// Newton's solver (hinge/sim/simulation.hpp, linear_solver.hpp, system.hpp): the system --dump-system
// writes is the incremental potential's gradient and true Hessian; Newton stops by the contract's rule;
// the solver report adds up; only the named effects' stencils enter the matrix; the solvers reject a
// matrix that is not positive definite.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>

#include "hinge/sim/linear_solver.hpp"
#include "sim_support.hpp"

namespace hinge::sim {
namespace {

// The dense symmetric matrix of an upper triangle.
Eigen::MatrixXd symmetric(const Eigen::SparseMatrix<double>& upper) {
  const Eigen::MatrixXd u = Eigen::MatrixXd(upper);
  Eigen::MatrixXd full = u + u.transpose();
  full.diagonal() = u.diagonal();
  return full;
}

// A 5 x 4 cloth falling onto a sphere with a pinned corner, every effect with a Hessian.
Scene falling_cloth() {
  Scene s = test::cloth(5, 4, 0.2, 0.15, 0.103);
  s.solve.mode = Mode::dynamic, s.solve.dt = 0.01, s.solve.steps = 2;
  s.solve.hessian = HessianTreatment::exact;
  s.velocity = {0.1, 0, -1};
  s.gravity = Gravity{{0, 0, -9.81}};
  s.stretching = Stretching{};
  s.bending = Bending{Model::tan, test::stiffness(s.material)};
  s.sphere = Sphere{{0, 0, 0}, 0.1};
  s.pins = Pins{{0}};
  return s;
}

// Central differences with step h = u^(1/3) L have error about C u^(2/3) = 4e-11 C relative to the
// derivative (effects_test.cpp); C below ~1e4 here (the barrier's length scale d_hat = 1e-3 against L
// = 0.05): bound 1e-6, normwise.
constexpr double kFiniteDifferenceTolerance = 1e-6;

TEST(Newton, TheDumpedSystemIsTheIncrementalPotentialsGradientAndTrueHessian) {
  const Scene s = falling_cloth();
  RunOptions o;
  o.dump = {{1, 2}};
  SystemDump kept;
  Mesh state;
  o.on_dump = [&](const SystemDump& d) {
    kept = d;
    state = *d.state;
  };
  Mesh last;
  const Summary summary = simulate(s, o, last);
  ASSERT_TRUE(summary.ok) << summary.reason;
  ASSERT_EQ(kept.step, 1);
  ASSERT_EQ(kept.iteration, 2);
  // The incremental potential of step 1: the effects' potential plus (x - x_hat)^T M (x - x_hat) / (2 dt^2),
  // x_hat = x0 + dt v0 (the pinned vertex does not move).
  test::Effects fx(s, s.solve.dt);
  Eigen::VectorXd x_hat = test::coordinates(s.mesh);
  for (Eigen::Index d = 3; d < x_hat.size(); ++d) x_hat[d] += s.solve.dt * s.velocity[static_cast<std::size_t>(d % 3)];
  const Eigen::VectorXd weight = fx.context.mass / (s.solve.dt * s.solve.dt);
  auto potential = [&](const Eigen::VectorXd& x, unsigned request) {
    Evaluation e = fx.evaluate(x, request);
    const Eigen::VectorXd dx = x - x_hat;
    e.energy += 0.5 * dx.dot(weight.cwiseProduct(dx));
    if (request & 2u) e.gradient += weight.cwiseProduct(dx);
    return e;
  };
  const Eigen::VectorXd x = test::coordinates(state);
  const Eigen::Index free = x.size() - 3;  // the pinned vertex 0's coordinates come first
  ASSERT_EQ(kept.gradient.size(), free);
  const double h = std::cbrt(test::u) * 0.05;
  Eigen::VectorXd g_fd(free);
  Eigen::MatrixXd H_fd(free, free);
  for (Eigen::Index i = 0; i < free; ++i) {
    Eigen::VectorXd plus = x, minus = x;
    plus[3 + i] += h, minus[3 + i] -= h;
    const Evaluation ep = potential(plus, 3), em = potential(minus, 3);
    g_fd[i] = (ep.energy - em.energy) / (2 * h);
    H_fd.col(i) = (ep.gradient - em.gradient).tail(free) / (2 * h);
  }
  EXPECT_LE((g_fd - kept.gradient).norm(), kFiniteDifferenceTolerance * kept.gradient.norm());
  const Eigen::MatrixXd H = symmetric(kept.hessian);
  EXPECT_LE((H_fd - H).norm(), kFiniteDifferenceTolerance * H.norm());
  // The matrix factored is positive definite (a Cholesky factorization of it exists).
  EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(symmetric(kept.factored)).info(), Eigen::Success);
}

// Between two Newton iterations k and k + 1 of a time step (states x_k, x_k+1, gradients g_k, g_k+1 and true
// Hessians H_k, H_k+1 dumped; dx = x_k+1 - x_k, dg = g_k+1 - g_k), Taylor's theorem: the tangent's remainder
// dg - H_k dx is the second-order term T[dx, dx] / 2 + O(|dx|^3), the trapezoid's dg - (H_k + H_k+1) dx / 2
// is O(|dx|^3), and a Hessian off by a first-order error E leaves E dx in both. Where the step is small
// enough for the second-order term to be a small part of dg (the tangent's remainder below dg / 5), the
// trapezoid's must be far below the tangent's: bound 1/10 (measured 0.001-0.036 on this step's 12
// iterations). The same check on Hessians 5% off fails on every such pair (measured 0.27-8.7): it has power.
TEST(Newton, TheDumpedHessianPredictsTheGradientsChangeToSecondOrder) {
  Scene s = falling_cloth();
  s.sphere.reset();          // a smooth potential: the barrier's d_hat = 1e-3 m is below these steps
  s.velocity = {3, -2, -5};  // a first step of 12 Newton iterations
  RunOptions o;
  for (int i = 1; i <= 12; ++i) o.dump.emplace_back(1, i);
  std::vector<SystemDump> kept;
  std::vector<Eigen::VectorXd> states;
  o.on_dump = [&](const SystemDump& d) {
    kept.push_back(d);
    states.push_back(test::coordinates(*d.state).tail(d.gradient.size()));  // the free coordinates
  };
  Mesh last;
  const Summary summary = simulate(s, o, last);
  ASSERT_TRUE(summary.ok) << summary.reason;
  int pairs = 0;
  for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
    const Eigen::VectorXd dx = states[k + 1] - states[k], dg = kept[k + 1].gradient - kept[k].gradient;
    const Eigen::MatrixXd H0 = symmetric(kept[k].hessian), H1 = symmetric(kept[k + 1].hessian);
    const double tangent = (dg - H0 * dx).norm();
    if (!(tangent <= 0.2 * dg.norm())) continue;
    ++pairs;
    EXPECT_LE((dg - 0.5 * (H0 + H1) * dx).norm(), 0.1 * tangent) << "iterations " << k + 1 << ", " << k + 2;
    EXPECT_GT((dg - 0.475 * (H0 + H1) * dx).norm(), 0.1 * tangent) << "iterations " << k + 1 << ", " << k + 2;
  }
  EXPECT_GE(pairs, 3);
}

// Writing a system takes the true Hessian into the matrix the run factors; the run must go on with the
// matrix it factored (the trust region measures its steps in that matrix's norm): the same bits either way.
TEST(Newton, DumpingSystemsChangesNoBitOfTheRun) {
  Scene s = falling_cloth();
  s.sphere.reset();
  s.velocity = {3, -2, -5};  // steps that take the projected rung (its norm is the projected matrix's)
  s.solve.steps = 4;
  RunOptions dumping;
  for (int step = 1; step <= 4; ++step)
    for (int i = 1; i <= 12; ++i) dumping.dump.emplace_back(step, i);
  int dumps = 0;
  dumping.on_dump = [&](const SystemDump&) { ++dumps; };
  Mesh plain, dumped;
  const Summary a = simulate(s, {}, plain), b = simulate(s, dumping, dumped);
  ASSERT_TRUE(a.ok && b.ok) << a.reason << b.reason;
  EXPECT_GT(dumps, 6);
  EXPECT_EQ(a.newton_iterations, b.newton_iterations);
  EXPECT_EQ(test::coordinates(plain), test::coordinates(dumped));
}

TEST(Newton, AStaticSolveStopsWithTheResidualWithinTheContractsTolerance) {
  Scene s = test::cloth(7, 3, 0.3, 0.1);
  s.material.young = 1e8, s.material.thickness = 1e-3;
  s.gravity = Gravity{{0, 0, -9.81}};
  s.stretching = Stretching{};
  s.bending = Bending{Model::tan, test::stiffness(s.material)};
  s.pins = Pins{{0, 7, 14}};
  s.solve.hessian = HessianTreatment::exact;
  s.solve.max_newton = 1000;
  Mesh last;
  const Summary summary = simulate(s, {}, last);
  ASSERT_TRUE(summary.ok) << summary.reason;
  test::Effects fx(s);
  const Evaluation e = fx.evaluate(test::coordinates(last), 3);
  // F = max_v m_v |g|: the stop rule's scale; the residual on the free vertices at most 1e-8 F.
  const double F = fx.context.mass.maxCoeff() * 9.81;
  double residual = 0;
  for (Index v = 0; v < 21; ++v)
    if (v % 7 != 0) residual = std::max(residual, e.gradient.segment<3>(3 * v).norm());
  EXPECT_LE(residual, s.solve.residual_tolerance * F);
  EXPECT_GT(residual, 0);
}

TEST(Newton, TheSolverReportAddsUp) {
  Scene s = falling_cloth();
  s.solve.steps = 20;
  Mesh last;
  const Summary summary = simulate(s, {}, last);
  ASSERT_TRUE(summary.ok) << summary.reason;
  const auto& r = summary.solver;
  EXPECT_EQ(r.newton + r.projected + r.shifted_rung + r.gradient, summary.newton_iterations);
  EXPECT_GE(r.factorizations, r.newton + r.projected + r.shifted_rung);  // each of those rungs factored at least once
  EXPECT_GE(r.factorizations, r.shifted);
  EXPECT_GE(static_cast<double>(r.newton_max), r.newton_median);
  EXPECT_LE(r.newton_max, summary.newton_iterations);
  EXPECT_LE(r.limited, summary.newton_iterations);  // iterations, each counted once
  EXPECT_TRUE(r.linear_solver == "cholmod supernodal LL^T" || r.linear_solver == "cholmod simplicial LL^T");
}

TEST(Newton, OnlyTheNamedEffectsStencilsEnterTheMatrix) {
  Scene s = test::cloth(6, 5, 0.3, 0.2);
  const Topology t = build_topology(s.mesh);
  const auto n = static_cast<Slot>(t.vertex_count);
  s.gravity = Gravity{{0, 0, -9.81}};
  EXPECT_EQ(Sparsity(t, couplings(s)).nonzeros(), 3 * n);  // gravity alone: a diagonal
  s.sphere = Sphere{{0, 0, -1}, 0.5};
  EXPECT_EQ(Sparsity(t, couplings(s)).nonzeros(), 6 * n);  // each vertex's 3 x 3 block's upper triangle
  s.stretching = Stretching{};
  const Slot faces = Sparsity(t, couplings(s)).nonzeros();
  s.bending = Bending{Model::tan, 1e-3};
  const Slot hinges = Sparsity(t, couplings(s)).nonzeros();
  // Stretching adds a 3 x 3 block per edge (the vertex pairs of the faces), bending one per hinge (x0, x3).
  EXPECT_EQ(faces, 6 * n + 9 * static_cast<Slot>(t.edges.size()));
  EXPECT_EQ(hinges, faces + 9 * static_cast<Slot>(t.hinges.size()));
}

TEST(Newton, BothSolversRejectAMatrixThatIsNotPositiveDefiniteAndSolveOneThatIs) {
  Eigen::SparseMatrix<double> a(3, 3);
  a.insert(0, 0) = 2, a.insert(0, 1) = 1, a.insert(1, 1) = 2, a.insert(2, 2) = 1;
  a.makeCompressed();
  for (auto kind : {LinearSolver::cholmod, LinearSolver::ldlt}) {
    auto solver = make_sparse_solver(kind);
    solver->analyze(a);
    ASSERT_TRUE(solver->factorize(a));
    const Eigen::VectorXd x = solver->solve(Eigen::Vector3d(3, 3, 1));
    // [[2, 1], [1, 2]] x = (3, 3): x = (1, 1); condition number 3, a few roundings: 8 u.
    EXPECT_NEAR(x[0], 1, 8 * test::u);
    EXPECT_NEAR(x[1], 1, 8 * test::u);
    EXPECT_EQ(x[2], 1);
    Eigen::SparseMatrix<double> b = a;
    b.coeffRef(1, 1) = 0.25;  // det of the 2 x 2 block: 0.5 - 1 < 0
    EXPECT_FALSE(solver->factorize(b));
  }
}

}  // namespace
}  // namespace hinge::sim
