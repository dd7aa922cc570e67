// The report of a bending term's conformance (hinge/conformance/energy_report.hpp).
#include "hinge/conformance/energy_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "hinge/conformance/energy_diagnosis.hpp"

namespace hinge::conformance {
namespace {

std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) {
    if (!out.empty()) out += ", ";
    out += n;
  }
  return out;
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
  const bool projected = energy.problem.hessian == HessianKind::projected;
  if (projected) grading.best = Tier::policy;  // the reference is not certified
  if (energy.diagonal_blocks)
    for (CandidateResult& r : results) keep_diagonal_blocks(r.hess.data());
  Report r = make_report(std::move(candidate), std::move(expected), std::move(results), grading, stencil,
                         depth_name(set.depth));
  r.settings = {{"energy", energy_name(energy.problem)},
                {"weight", energy.weight},
                {"k", number(energy.problem.k)},
                {"hessian", hessian_kind_name(energy.problem.hessian)},
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
  if (projected)
    r.notes.push_back(
        "hessian=\"projected\": not certified: 256-bit reference (each hinge's exact Hessian with its "
        "negative eigenvalues set to zero, evaluated at 256 bits and rounded to double); a passing "
        "category's tier is at best policy");
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

EnergyGrading energy_grading(const std::string& energy, const std::string& weight, double k, const std::string& hessian,
                             bool diagonal_blocks) {
  static const std::vector<std::string> energies{"shells", "tan", "willmore", "bridson", "quadratic", "custom"};
  if (energy == "viscoelastic")
    throw std::invalid_argument("energy \"viscoelastic\" is not graded (it needs the previous state and a time step)");
  if (std::find(energies.begin(), energies.end(), energy) == energies.end()) {
    std::string why = "unknown energy \"";
    why += energy;
    why += "\" (choices: ";
    why += joined(energies);
    why += ")";
    throw std::invalid_argument(why);
  }
  if (hessian != "exact" && hessian != "gauss-newton" && hessian != "projected") {
    std::string why = "unknown Hessian treatment \"";
    why += hessian;
    why += "\" (choices: exact, gauss-newton, projected)";
    throw std::invalid_argument(why);
  }
  if (!(k > 0 && std::isfinite(k))) {
    std::string why = "the stiffness k must be finite and positive; got ";
    why += number(k);
    throw std::invalid_argument(why);
  }
  EnergyGrading g;
  g.custom = energy == "custom";
  g.problem.quadratic = energy == "quadratic";
  if (g.problem.quadratic && hessian != "exact")
    throw std::invalid_argument("the quadratic energy's Hessian is constant: only the treatment \"exact\" is graded");
  if (g.problem.quadratic && weight != "contract" && weight != "none")
    throw std::invalid_argument("the quadratic energy takes no weight (its 3 / A_bar is part of its definition)");
  g.problem.model = parse_model(g.custom || g.problem.quadratic ? "shells" : energy);
  g.problem.k = k;
  g.problem.hessian = hessian == "gauss-newton" ? HessianKind::gauss_newton
                      : hessian == "projected"  ? HessianKind::projected
                                                : HessianKind::exact;
  g.weight = g.problem.quadratic ? "none" : weight;
  g.diagonal_blocks = diagonal_blocks;
  return g;
}

ConsistencyPlan energy_consistency_plan(const EnergySet& set, Dtype dtype) {
  std::vector<EnergyCase> base;
  for (const std::size_t i : consistency_base(set)) base.push_back(set.cases[i]);
  return consistency_plan(base, dtype);
}

std::vector<std::string> consistency_probe_ids(const ConsistencyPlan& plan) {
  std::vector<std::string> ids(plan.x.size());
  for (std::size_t i = 0; i < plan.base.size(); ++i)
    for (std::size_t n = 0; n < probes_per_case; ++n) {
      std::string& id = ids.at(plan.first[i] + n);
      id = consistency_category;
      id += '/';
      id += plan.base[i].id;
      id += '/';
      id += std::to_string(n);
    }
  return ids;
}

EnergyOutputs probe_outputs(const CandidateResult& r) {
  EnergyOutputs o;
  o.ok = r.status == CandidateResult::Status::ok;
  o.energy = r.theta;
  o.grad = r.grad;
  o.hess = r.hess;
  return o;
}

Report grade_energy(std::string candidate, const EnergySet& set, const EnergyGrading& energy, const Grading& grading,
                    std::vector<double> weights, std::vector<CandidateResult> results,
                    const std::vector<EnergyOutputs>& probes, const Stencil& stencil) {
  // The contract's weight, not given per case: the oracle's fast path; any other weight: its interval path.
  // quadratic takes no weight: the contract's stands in as the consistency checks' normalizer c = k w.
  const bool fast_path = weights.empty() && (energy.weight == "contract" || energy.problem.quadratic);
  if (weights.empty()) weights = set_weights(set, energy.problem.quadratic ? "contract" : energy.weight);
  if (weights.size() != set.cases.size()) throw std::invalid_argument("grade_energy: one weight per case of the set");
  if (!energy.custom && results.size() != set.cases.size())
    throw std::invalid_argument("grade_energy: one result per case of the set");
  if (energy.custom && !results.empty())
    throw std::invalid_argument("grade_energy: energy \"custom\" is graded on the consistency probes alone");

  // The consistency checks on the probes, each normalized by its base case's c = k w.
  const ConsistencyPlan plan = energy_consistency_plan(set, grading.dtype);
  if (probes.size() != plan.x.size()) throw std::invalid_argument("grade_energy: one output per consistency probe");
  std::vector<double> c;
  for (const std::size_t i : consistency_base(set)) c.push_back(energy.problem.k * weights[i]);
  ConsistencyOptions options;
  options.dtype = grading.dtype;
  options.energy_given = grading.given[0];
  options.grad_given = grading.given[1];
  options.hess_given = grading.given[2];
  options.hessian_exact = energy.problem.hessian == HessianKind::exact;
  options.diagonal_blocks = energy.diagonal_blocks;
  std::vector<ConsistencyCheck> checks = consistency_checks(plan, probes, c, options);

  std::vector<Expected> expected;
  if (!energy.custom)
    expected = energy_expectations(set, energy.problem, fast_path ? std::vector<double>{} : weights, grading.dtype,
                                   energy.diagonal_blocks);
  return make_energy_report(std::move(candidate), set, std::move(expected), weights, std::move(results), grading,
                            energy, std::move(checks), stencil);
}

}  // namespace hinge::conformance
