// hinge/sim/summary.hpp: summary.json of `hinge simulate` (the contract's keys, in its order; every number
// reads back exactly).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "hinge/sim/simulation.hpp"

namespace hinge::sim {

// `build`: how the program was built (version, commit, compiler, flags, ...), written as "build".
std::string summary_json(const Summary& summary, const std::vector<std::pair<std::string, std::string>>& build);

}  // namespace hinge::sim
