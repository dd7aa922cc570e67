// hinge/conformance/energy_report.hpp: the report of a bending term's conformance (docs/energy-conformance.md):
// the graded run of report.hpp on the energy cases (groups energy, grad, hess; the rest hinge with each
// case), the energy diagnosis (energy_diagnosis.hpp), what was left out and the settings it was graded with.
#pragma once

#include <string>
#include <vector>

#include "hinge/conformance/energy_sets.hpp"
#include "hinge/conformance/report.hpp"

namespace hinge::conformance {

// How a bending term is graded, beyond the Grading: the energy, its stiffness and Hessian treatment, its
// weight ("contract", a name of weight_names(), or "callable": the weights given per case), and whether only
// the Hessian's four diagonal 3 x 3 blocks are graded.
struct EnergyGrading {
  EnergyProblem problem;
  std::string weight = "contract";
  bool diagonal_blocks = false;
  bool custom = false;  // energy "custom": nothing graded against the oracle, the consistency checks only
};

// Grades `results` (the contract's order) on `set`'s cases against `expected` (energy_expectations with the
// same `weights`: one per case, the w each term was given). With diagonal_blocks, the candidate's entries
// outside the diagonal blocks are ignored (set to zero, as in the expectations). The report's notes say
// what was left out and what was not graded.
// `checks`: the consistency checks' results (consistency.hpp), which the report shows and which must pass.
// With energy.custom, `expected` and `results` are empty and the checks alone decide.
Report make_energy_report(std::string candidate, const EnergySet& set, std::vector<Expected> expected,
                          const std::vector<double>& weights, std::vector<CandidateResult> results, Grading grading,
                          const EnergyGrading& energy, std::vector<ConsistencyCheck> checks,
                          const Stencil& stencil = contract_stencil);

// The indices (into set.cases) of the consistency checks' base hinges: the well-shaped deformed hinges.
std::vector<std::size_t> consistency_base(const EnergySet& set);

// The weights of `set`'s cases for a named weight (named_weight on each rest hinge).
std::vector<double> set_weights(const EnergySet& set, const std::string& weight);

}  // namespace hinge::conformance
