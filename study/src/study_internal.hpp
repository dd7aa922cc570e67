// The parts of the study run() puts together (study.cpp), besides the rows (rows.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "hinge/study/study.hpp"

namespace hinge::study::detail {

class Prepared;
struct Measured;  // timing.hpp

// The rows in double alone (double_rows.cpp): the faithful mode, the certified oracle (fast path on, its
// escalation per category), an outside implementation (its errors on every prepared hinge, its rounds in
// its own process).
Measured measure_faithful(const Prepared& p, double budget, bool quick);
Measured measure_oracle(const Prepared& p, double budget, bool quick);
Measured measure_outside(const Outside& o, const Prepared& p, double budget, bool quick);

// Whole-mesh evaluations of `method` in `scalar` on the cloth of each size n (n x n vertices), in
// increasing order while the budget lasts (at least one size), and the fitted power law.
MeshRow measure_mesh(methods::Method method, const ScalarType& scalar, const std::vector<int>& sizes, double budget,
                     bool quick);

// The paper's Table 2 from the mesh rows of one scalar type (hinge::io::SharedFit): k shared by the methods,
// the mean of their fitted k over the paper's sizes (11^2 .. 81^2), each method's ln a refitted with it.
SharedFit shared_fit(const std::vector<MeshRow>& mesh, ScalarType::Kind kind);

// The processor's name (/proc/cpuinfo), or "unknown".
std::string cpu_name();

}  // namespace hinge::study::detail
