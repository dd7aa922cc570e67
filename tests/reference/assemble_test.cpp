// Mesh assembly (assemble.hpp): the energy gradient against finite differences of the energy, the
// Hessian against the per-hinge energy Hessians (eqs. (2)-(3)), rest state = deformed state, and errors
// that name the hinge.
#include <gtest/gtest.h>

#include <random>

#include "hinge/core/errors.hpp"
#include "hinge/reference/assemble.hpp"
#include "hinge/reference/evaluate.hpp"

namespace hinge::reference {
namespace {

// An n x n grid of vertices with both diagonal directions, bumped out of plane.
Mesh bumpy_grid(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.vertices.push_back({i + jitter(rng), j + jitter(rng), std::sin(i * 0.9) * std::cos(j * 0.7) + jitter(rng)});
  auto v = [n](int i, int j) { return static_cast<Index>(j * n + i); };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      if ((i + j) % 2) {
        m.faces.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
        m.faces.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      } else {
        m.faces.push_back({v(i, j), v(i + 1, j), v(i, j + 1)});
        m.faces.push_back({v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  return m;
}

TEST(Assemble, GradientMatchesFiniteDifferencesOfTheEnergy) {
  set_mpfr_bits(256);
  const Mesh rest = bumpy_grid(4, 1);
  Mesh deformed = bumpy_grid(4, 2);
  const Topology t = build_topology(rest);
  for (Model model : {Model::shells, Model::tan, Model::willmore, Model::bridson}) {
    const auto c = rest_state<mpfr>(rest, t, {model, 0.5, 0});
    const auto m = assemble<mpfr>(deformed, t, c, model);
    // Steps of 2^-30 on exact doubles; central differences in 256 bits: truncation ~2^-60 relative.
    const double h = 0x1p-30;
    for (std::size_t v = 0; v < deformed.vertices.size(); v += 3)
      for (int k = 0; k < 3; ++k) {
        Mesh plus = deformed, minus = deformed;
        plus.vertices[v][k] += h;
        minus.vertices[v][k] -= h;
        const mpfr fd = (assemble<mpfr>(plus, t, c, model, want_energy).energy -
                         assemble<mpfr>(minus, t, c, model, want_energy).energy) /
                        (2 * h);
        EXPECT_LT(to_double(abs(fd - m.gradient[3 * v + k])), 1e-15 * (1 + to_double(abs(m.energy))))
            << model_name(model) << " vertex " << v << " coordinate " << k;
      }
  }
}

TEST(Assemble, HessianIsTheSumOfHingeHessians) {
  const Mesh rest = bumpy_grid(5, 3), deformed = bumpy_grid(5, 4);
  const Topology t = build_topology(rest);
  const auto c = rest_state<double>(rest, t, {Model::tan, 1.0, 0});
  const auto m = assemble<double>(deformed, t, c, Model::tan);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(m.hessian.rows(), m.hessian.cols());
  for (std::size_t i = 0; i < t.hinges.size(); ++i) {
    const auto d = theta_derivatives<double>(hinge_coordinates(deformed, t.hinges[i]));
    const auto H = energy_hessian(psi(Model::tan, c[i], d.angle), d.grad, d.hess);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        dense.block<3, 3>(3 * t.hinges[i].x[a], 3 * t.hinges[i].x[b]) += H.block<3, 3>(3 * a, 3 * b);
  }
  const Eigen::SparseMatrix<double> full = m.hessian.selfadjointView<Eigen::Upper>();
  const Eigen::MatrixXd assembled(full);
  // The same per-hinge products summed in another order: a few units of 2^-53 of the largest entries.
  EXPECT_LE((assembled - dense).norm(), 16 * 0x1p-53 * dense.norm());
  for (Eigen::Index col = 0; col < m.hessian.outerSize(); ++col)  // upper storage: row <= col
    for (Eigen::SparseMatrix<double>::InnerIterator it(m.hessian, col); it; ++it) EXPECT_LE(it.row(), it.col());
}

TEST(Assemble, RestStateHasZeroEnergyAndGradient) {
  const Mesh mesh = bumpy_grid(4, 5);
  const Topology t = build_topology(mesh);
  for (Model model : {Model::shells, Model::tan}) {
    const auto m = assemble<double>(mesh, t, rest_state<double>(mesh, t, {model, 1.0, 0}), model);
    EXPECT_EQ(m.energy, 0.0);
    EXPECT_EQ(m.gradient.norm(), 0.0);
  }
}

TEST(Assemble, OnlyRequestedOutputsAreComputed) {
  const Mesh mesh = bumpy_grid(3, 6);
  const Topology t = build_topology(mesh);
  const auto m = assemble<double>(mesh, t, rest_state<double>(mesh, t, {}), Model::tan, want_energy);
  EXPECT_EQ(m.gradient.size(), 0);
  EXPECT_EQ(m.hessian.size(), 0);
}

TEST(Assemble, DegenerateHingeIsNamed) {
  Mesh mesh = bumpy_grid(3, 7);
  const Topology t = build_topology(mesh);
  const auto c = rest_state<double>(mesh, t, {Model::shells, 1.0, 0});
  mesh.vertices[4] = mesh.vertices[1];  // the centre onto a neighbour: a zero-length edge, zero-area faces
  try {
    assemble<double>(mesh, t, c, Model::shells);  // finite at theta = pi: the degeneracy is the error
    FAIL() << "degenerate mesh accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hinge "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("OBJ numbering"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hinge::reference
