// hinge/conformance/report.hpp: the report of `hinge conform` (docs/conformance.md): per category the
// median and worst errors, the missing and non-finite results, the tier reached and the worst case; as
// text and as JSON (`--json`).
#pragma once

#include <array>
#include <iosfwd>
#include <string>
#include <vector>

#include "hinge/conformance/grading.hpp"

namespace hinge::conformance {

struct CategorySummary {
  std::string category;
  int cases = 0, missing = 0, nonfinite = 0, failed = 0;
  std::array<double, 3> median{}, worst{};  // per group, units of 2^-53
  std::string worst_id;                     // the case with the largest error / tolerance
  double worst_ratio = 0;
  bool pass = true;
  Tier tier = Tier::correctly_rounded;  // the tier every case of the category reaches
};

std::vector<CategorySummary> summarize(const std::vector<CaseOutcome>& outcomes);

// The report of hinge conform; returns whether everything passed.
bool print_report(std::ostream& out, const std::vector<CaseOutcome>& outcomes, const Policy& policy,
                  const std::string& candidate);
// The same report as JSON (hinge conform --json; docs/conformance.md, "The JSON report"), every case included.
void write_json_report(std::ostream& out, const std::vector<CaseOutcome>& outcomes, const Policy& policy,
                       const std::string& candidate);

}  // namespace hinge::conformance
