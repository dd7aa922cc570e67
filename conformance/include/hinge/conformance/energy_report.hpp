// hinge/conformance/energy_report.hpp: the report of a bending term's conformance (docs/energy-conformance.md):
// the graded run of report.hpp on the energy cases (groups energy, grad, hess; the rest hinge with each
// case), the energy diagnosis (energy_diagnosis.hpp), what was left out and the settings it was graded with.
#pragma once

#include <string>
#include <vector>

#include "hinge/conformance/consistency.hpp"
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

// The grading of a bending term named as hinge.conform_energy and `hinge conform --energy` name it: `energy`
// "shells", "tan", "willmore", "bridson" or "custom" (problem.model shells: the consistency checks run on the
// shells set's base hinges), `hessian` "exact" or "gauss-newton", k finite and positive, `weight` the label the
// report shows (a name of weight_names(), or "callable"; not checked here: set_weights checks a name). Throws
// std::invalid_argument naming the choices, or saying what is not graded yet ("quadratic", "projected") or
// not at all ("viscoelastic"). Its set: energy_set(grading.problem.model).
EnergyGrading energy_grading(const std::string& energy, const std::string& weight, double k, const std::string& hessian,
                             bool diagonal_blocks = false);

// The consistency checks' probes of `set` (its consistency_base, each with its rest hinge), in `dtype`.
ConsistencyPlan energy_consistency_plan(const EnergySet& set, Dtype dtype);

// How the command line's files name the probes: "consistency/<base id>/<n>", n = 0 ... probes_per_case - 1 the
// probe's place in its base case's layout (consistency.hpp), index-aligned with plan.x; their category.
std::vector<std::string> consistency_probe_ids(const ConsistencyPlan& plan);
inline constexpr const char* consistency_category = "consistency";

// A probe's outputs as the consistency checks take them (ok when r is ok).
EnergyOutputs probe_outputs(const CandidateResult& r);

// Grades a bending term from its outputs, whatever route collected them (hinge.conform_energy from Python,
// `hinge conform --energy` from a plugin or a file): `results` on set.cases (the contract's order; empty with
// energy.custom), `probes` on energy_consistency_plan(set, grading.dtype)'s probes; `weights` w per case of
// the set (empty: set_weights(set, energy.weight)), each check normalized by c = k w of its base case. The
// expectations are energy_expectations' (the oracle's fast path for the contract's weight when `weights` is
// empty, its interval path otherwise), the report make_energy_report's. Throws std::invalid_argument when the
// sizes do not match the set or the plan, or a weight is unknown.
Report grade_energy(std::string candidate, const EnergySet& set, const EnergyGrading& energy, const Grading& grading,
                    std::vector<double> weights, std::vector<CandidateResult> results,
                    const std::vector<EnergyOutputs>& probes, const Stencil& stencil = contract_stencil);

}  // namespace hinge::conformance
