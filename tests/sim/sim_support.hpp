// Scenes built in memory for the simulator's tests, and the total potential of a scene's effects.
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>

#include "hinge/core/samples.hpp"
#include "hinge/sim/effect.hpp"
#include "hinge/sim/scene.hpp"
#include "hinge/sim/simulation.hpp"
#include "hinge/sim/system.hpp"

namespace hinge::sim::test {

// k from the material by eq. (11), as a scene without "k" gets it.
inline double stiffness(const Material& m) { return bending_stiffness(m.young, m.poisson, m.thickness); }

constexpr double u = std::numeric_limits<double>::epsilon() / 2;  // unit roundoff of double

// A cloth of nx x ny vertices, lx x ly metres, in the xy plane at height z; material of a light cloth.
inline Scene cloth(int nx, int ny, double lx, double ly, double z = 0) {
  Scene s;
  s.file = "test-scene.json";
  s.name = "test";
  s.mesh = grid_mesh(nx, ny, lx, ly, {0, 0, z}, "xy");
  s.rest = s.mesh;
  s.material = {400, 2e6, 0.3, 5e-4};
  return s;
}

// The effects of a scene with what they share (topology, structure, masses), kept alive together.
struct Effects {
  explicit Effects(const Scene& scene, double dt = 0, int threads = 1)
      : scene_(scene), topology(build_topology(scene.mesh)), sparsity(topology) {
    context.scene = &scene_, context.topology = &topology, context.sparsity = &sparsity;
    context.mass = lumped_mass(scene_);
    context.dt = dt;
    context.threads = threads;
    all = make_effects(context);
  }
  // The sum of every effect's part at x.
  Evaluation evaluate(const Eigen::VectorXd& x, unsigned request = 7, Treatment treatment = Treatment::scene) {
    Evaluation e;
    e.request = request;
    e.treatment = treatment;
    e.gradient.setZero(x.size());
    e.hessian.assign(static_cast<std::size_t>(sparsity.nonzeros()), 0.0);
    for (auto& effect : all) effect->add(x, e);
    return e;
  }
  // The full symmetric Hessian of an evaluation, dense.
  Eigen::MatrixXd dense(const Evaluation& e) const {
    Eigen::SparseMatrix<double> h = sparsity.structure();
    std::copy(e.hessian.begin(), e.hessian.end(), h.valuePtr());
    Eigen::MatrixXd upper = Eigen::MatrixXd(h);
    Eigen::MatrixXd full = upper + upper.transpose();
    full.diagonal() = upper.diagonal();
    return full;
  }
  Scene scene_;
  Topology topology;
  Sparsity sparsity;
  Context context;
  std::vector<std::unique_ptr<Effect>> all;
};

inline Eigen::VectorXd coordinates(const Mesh& m) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(3 * m.vertices.size()));
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    for (std::size_t c = 0; c < 3; ++c) x[static_cast<Eigen::Index>(3 * v + c)] = m.vertices[v][c];
  return x;
}

// A scene file written into a fresh folder under the system's temporary directory.
inline std::filesystem::path write_scene(const std::string& name, const std::string& json) {
  const auto dir = std::filesystem::temp_directory_path() / ("hinge-sim-test-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "scene.json") << json;
  return dir / "scene.json";
}

}  // namespace hinge::sim::test
