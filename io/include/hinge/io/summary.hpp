// hinge/io/summary.hpp: summary.json of `hinge simulate` (docs/contract.md: the contract's keys, in its
// order; every number reads back exactly): what a run reports, and its writer.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace hinge::io {

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
};

// `build`: how the program was built (hinge/core/build_info.hpp), written as "build".
std::string summary_json(const Summary& summary, const std::vector<std::pair<std::string, std::string>>& build);

}  // namespace hinge::io
