// hinge/sim/simulation.hpp: running a scene. Static: Newton with a trust region on the total potential.
// Dynamic: backward Euler, v+ = v + dt M^-1 f(x+), x+ = x + dt v+, each step Newton on the incremental
// potential 1/(2 dt^2) (x - x_hat)^T M (x - x_hat) + V(x) (+ damping's dissipation), x_hat = x + dt v.
// Each Newton iteration takes its direction from the first rung of a fallback chain that gives a positive
// definite matrix (the scene's treatment; every element's Hessian projected; a shift scaled to the mass
// matrix; a gradient step), and Newton stops by the contract's rule: the largest force residual on a free
// vertex at most residual_tolerance times the scene's force scale, and the last step of the newton or
// projected rung below newton_tolerance times the longest rest edge (docs/simulator.md).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hinge/io/summary.hpp"
#include "hinge/sim/scene.hpp"

namespace hinge::sim {

// What a run reports (summary.json; the format is hinge::io's: hinge/io/summary.hpp).
using io::Summary;

// The linear system of one Newton iteration, on the free coordinates in ascending 3 v + c order (for
// --dump-system): the true Hessian of the total (incremental) potential, every effect's every term exact
// whatever the treatment; the matrix factored for the iteration's step; the gradient; the state.
struct SystemDump {
  int step = 0, iteration = 0;                    // the step from 1 (a static solve: 0), the Newton iteration from 1
  Eigen::SparseMatrix<double> hessian, factored;  // upper triangles
  Eigen::VectorXd gradient;
  const Mesh* state = nullptr;
};

// One Newton iteration, as it went (for --newton-log).
struct IterationReport {
  int step = 0, iteration = 0;  // as SystemDump's
  const char* rung = "";        // "newton", "projected", "shifted" or "gradient"
  double residual = 0;          // the largest force residual on a free vertex, over F (the stop rule's scale)
  double energy = 0;            // the potential Newton minimizes, at the iteration's start
  double step_length = 0;       // the largest vertex displacement of the rung's step (P^-1 b), over L
  double alpha = 1;             // the fraction of the step tried that an effect's step limit allowed
  bool boundary = false;        // the trust region's boundary cut the step (newton and projected rungs)
};

struct RunOptions {
  int threads = 1;  // changes no output bit
  // The (step, iteration) pairs whose system on_dump receives (its time is not counted in time_s).
  std::vector<std::pair<int, int>> dump;
  std::function<void(const SystemDump&)> on_dump;
  // Called after every Newton iteration (its time is counted).
  std::function<void(const IterationReport&)> on_iteration;
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
