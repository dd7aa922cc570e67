// hinge/conformance/report.hpp: the report of a conformance run (docs/conformance.md): per category the
// median and worst errors, the missing and non-finite results, the tier reached and the worst case; the
// diagnosis; as text (`hinge conform`, str(report) in Python), as JSON (`--json`, report.to_json()) and
// as a self-contained HTML page (`--report FILE.html`, report.to_html(path); html_report.hpp).
#pragma once

#include <array>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "hinge/conformance/consistency.hpp"
#include "hinge/conformance/diagnosis.hpp"
#include "hinge/conformance/grading.hpp"

namespace hinge::conformance {

struct CategorySummary {
  std::string category;
  int cases = 0, missing = 0, nonfinite = 0, failed = 0;
  std::array<double, 3> median{}, worst{};  // per group, units of u (NaN for a group not given)
  std::string worst_id;                     // the case with the largest error / tolerance
  std::size_t worst_index = 0;              // its index in Report::outcomes
  double worst_ratio = 0;
  bool pass = true;
  Tier tier = Tier::correctly_rounded;  // the tier every case of the category reaches
};

std::vector<CategorySummary> summarize(const std::vector<CaseOutcome>& outcomes);

// A graded run, everything the three reports show.
struct Report {
  std::string candidate;  // what was checked: "plugin LIB.so (hinge_candidate)", "Python function f", ...
  Grading grading;
  std::string depth = "quick";           // "quick" or "deep"
  Stencil stencil = contract_stencil;    // the candidate's declared vertex order
  std::vector<Expected> expected;        // the cases, in report order
  std::vector<CandidateResult> results;  // the candidate's outputs, the contract's order, rounded to the dtype
  std::vector<CaseOutcome> outcomes;     // index-aligned with expected and results
  std::vector<CategorySummary> categories;
  std::vector<Finding> diagnosis;
  std::vector<std::string> notes;  // what else the reader should know ("the batch call raised ...")
  // What the outputs were graded as, beyond the dtype and depth (energy_report.hpp: energy, weight, k,
  // hessian, blocks), in the order shown.
  std::vector<std::pair<std::string, std::string>> settings;
  // Bending energies: the consistency checks (consistency.hpp), each one that fails failing the run.
  std::vector<ConsistencyCheck> checks;
  bool passed = false;
  Tier tier = Tier::fail;  // the lowest category tier
};

// Grades `results` against `expected` (index-aligned), summarizes, diagnoses.
Report make_report(std::string candidate, std::vector<Expected> expected, std::vector<CandidateResult> results,
                   const Grading& grading, const Stencil& stencil = contract_stencil, std::string depth = "quick");

// The candidate's order of a case's 12 coordinates (x_candidate).
std::array<double, 12> candidate_order(const std::array<double, 12>& x, const Stencil& stencil);

// The text report (hinge conform, str(report)).
void print_report(std::ostream& out, const Report& report);
// The JSON report (hinge conform --json, report.to_json(); docs/conformance.md, "The JSON report"): version
// 2's keys, every case included, plus "diagnosis" and per category "worst_case_detail".
void write_json_report(std::ostream& out, const Report& report);

}  // namespace hinge::conformance
