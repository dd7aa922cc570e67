// The report of a bending term's conformance (hinge/conformance/energy_report.hpp).
#include "hinge/conformance/energy_report.hpp"

#include <cstdio>

#include "hinge/conformance/energy_diagnosis.hpp"

namespace hinge::conformance {
namespace {

const char* hessian_name(HessianKind h) { return h == HessianKind::exact ? "exact" : "gauss-newton"; }

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

}  // namespace

std::vector<std::size_t> consistency_base(const EnergySet& set) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < set.cases.size(); ++i)
    if (set.cases[i].category.starts_with("well-shaped/")) out.push_back(i);
  return out;
}

std::vector<double> set_weights(const EnergySet& set, const std::string& weight) {
  std::vector<double> w;
  w.reserve(set.cases.size());
  for (const EnergyCase& c : set.cases) w.push_back(named_weight(weight, c.rest));
  return w;
}

Report make_energy_report(std::string candidate, const EnergySet& set, std::vector<Expected> expected,
                          const std::vector<double>& weights, std::vector<CandidateResult> results, Grading grading,
                          const EnergyGrading& energy, std::vector<ConsistencyCheck> checks, const Stencil& stencil) {
  grading.energy = true;
  if (energy.diagonal_blocks)
    for (CandidateResult& r : results) keep_diagonal_blocks(r.hess.data());
  Report r = make_report(std::move(candidate), std::move(expected), std::move(results), grading, stencil);
  r.settings = {{"energy", std::string(model_name(energy.problem.model))},
                {"weight", energy.weight},
                {"k", number(energy.problem.k)},
                {"hessian", hessian_name(energy.problem.hessian)},
                {"blocks", energy.diagonal_blocks ? "diagonal" : "full"}};
  if (energy.custom) r.settings[0].second = "custom";
  r.checks = std::move(checks);
  bool consistent = true;
  for (const ConsistencyCheck& c : r.checks) consistent = consistent && c.pass;
  r.passed = (energy.custom || r.passed) && consistent;
  if (energy.custom) {
    r.notes.push_back("energy \"custom\": nothing graded against certified values; the consistency checks only");
    return r;
  }
  r.diagnosis =
      diagnose_energy(r.expected, r.results, r.outcomes, r.grading, energy.problem, weights, energy.diagonal_blocks);
  if (!set.left_out.empty()) {
    std::size_t apart = 0;
    for (const std::string& why : set.left_out) apart += why.find("|theta - theta_bar| > pi") != std::string::npos;
    std::string note = std::to_string(set.left_out.size()) + " pairs left out, not graded: " + std::to_string(apart) +
                       " with |theta - theta_bar| > pi";
    if (apart != set.left_out.size())
      note += ", " + std::to_string(set.left_out.size() - apart) + " where the energy is infinite";
    r.notes.push_back(note);
  }
  if (energy.diagonal_blocks)
    r.notes.push_back(
        "blocks=\"diagonal\": only the Hessian's four 3 x 3 diagonal blocks were graded; its other entries "
        "were ignored");
  return r;
}

}  // namespace hinge::conformance
