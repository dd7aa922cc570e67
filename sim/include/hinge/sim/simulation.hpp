// hinge/sim/simulation.hpp: running a scene. Static: Newton with a backtracking line search on the total
// potential. Dynamic: backward Euler, v+ = v + dt M^-1 f(x+), x+ = x + dt v+, each step Newton on the
// incremental potential  1/(2 dt^2) (x - x_hat)^T M (x - x_hat) + V(x) (+ damping's dissipation),
// x_hat = x + dt v. Newton stops when the largest vertex displacement of a step is below
// newton_tolerance times the longest rest edge (docs/simulator.md: the Hessian treatments, the shift that
// makes a factorization or a non-descent direction succeed, the line search).
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hinge/io/summary.hpp"
#include "hinge/sim/scene.hpp"

namespace hinge::sim {

// What a run reports (summary.json; the format is hinge::io's: hinge/io/summary.hpp).
using io::Summary;

struct RunOptions {
  int threads = 1;  // changes no output bit
  // Called with every frame (dynamic: the initial state as frame 0, then every scene.output_every steps).
  std::function<void(int frame, const Mesh& state)> on_frame;
  // Progress: steps done of total (static: Newton iterations of max_newton).
  std::function<void(long long done, long long total)> on_progress;
};

// The lumped masses of the contract, per coordinate (3n): each vertex gets density * thickness * (the sum
// of its triangles' rest areas) / 3.
Eigen::VectorXd lumped_mass(const Scene& scene);

// Runs the scene; `final_state` receives the last state (the equilibrium of a static solve). A run that
// cannot go on returns ok = false with the reason (final_state then holds the last good state).
// Throws hinge::InputError for what the scene's effects reject before the run starts.
Summary simulate(const Scene& scene, const RunOptions& options, Mesh& final_state);

}  // namespace hinge::sim
