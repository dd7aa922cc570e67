// hinge/io/summary.hpp: summary.json of `hinge simulate` (docs/contract.md: the contract's keys, in its
// order; every number reads back exactly): what a run reports, and its writer.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace hinge::io {

// How Newton went (summary.json's "solver"; docs/simulator.md, "Newton").
struct SolverReport {
  long long factorizations = 0;  // every numerical factorization, a diagonal one included
  long long shifted = 0;         // those of a shifted matrix
  double newton_median = 0;      // Newton iterations per step (a static solve: its one step)
  long long newton_max = 0;
  // Newton iterations by the rung of the fallback chain that gave their step (they sum to
  // newton_iterations): the scene's treatment as it is, every element's Hessian projected, a shift added,
  // a gradient step.
  long long newton = 0, projected = 0, shifted_rung = 0, gradient = 0;
  long long halvings = 0;  // the line search's halvings in all
  long long limited = 0;   // iterations whose step an effect's step limit shortened
  std::string linear_solver;
};

struct Summary {
  std::string scene;
  bool ok = true;
  std::string reason;                // why a failed run stopped
  std::vector<std::string> effects;  // those that ran, in the contract's order
  std::size_t vertices = 0;
  int steps = 0;  // completed time steps (0 for a static solve)
  long long newton_iterations = 0;
  double time_total = 0, time_linear_solve = 0;  // seconds; total excludes writing files
  std::vector<std::pair<std::string, double>> time_effects;
  std::vector<std::pair<std::string, double>> energy;  // the effects with a potential, at the last state
  double bending_share = 0;
  SolverReport solver;
};

// `build`: how the program was built (hinge/core/build_info.hpp), written as "build".
std::string summary_json(const Summary& summary, const std::vector<std::pair<std::string, std::string>>& build);

}  // namespace hinge::io
