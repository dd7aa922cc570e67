// The parts of the study run() puts together (study.cpp), besides the rows (rows.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "hinge/study/study.hpp"

namespace hinge::study::detail {

// Whole-mesh evaluations of `method` in `scalar` on the cloth of each size n (n x n vertices), in
// increasing order while the budget lasts (at least one size), and the fitted power law.
MeshRow measure_mesh(methods::Method method, const ScalarType& scalar, const std::vector<int>& sizes, double budget,
                     bool quick);

// The processor's name (/proc/cpuinfo), or "unknown".
std::string cpu_name();

}  // namespace hinge::study::detail
