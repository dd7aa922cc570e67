// hinge/conformance/diagnosis.hpp: why a candidate fails (docs/conformance.md, "Diagnosis"). For each
// failing category the usual convention mismatches are tried on the candidate's outputs: theta negated,
// in degrees, unsigned, pi - |theta|, in [0, 2 pi), -pi on the branch cut; the gradient negated (a force);
// a Hessian with one matrix triangle filled or right; coordinate-major variables; the 24 orders of the
// four vertices, alone and with theta negated. A mismatch is named when, applied to every case of the
// category, it lifts the category to at least `approximate` and changes at least one case by more than
// its tolerance; mismatches that explain the same outputs are named once, the simplest first.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hinge/conformance/grading.hpp"

namespace hinge::conformance {

// The candidate's vertex order: its vertex j is the contract's x_{stencil[j]} (docs/contract.md).
using Stencil = std::array<int, 4>;
inline constexpr Stencil contract_stencil{0, 1, 2, 3};
// "(x0, x3, x1, x2)".
std::string stencil_name(const Stencil& s);

// One named mismatch.
struct Finding {
  std::string key;                      // a stable identifier: "theta-negated", "order:x0,x3,x1,x2", ...
  std::string explanation;              // "theta negated (the same as the stencil (x0, x2, x1, x3))"
  std::string change;                   // what to change: the stencil to declare, or the convention to fix
  std::vector<std::string> categories;  // the failing categories it explains, in report order
  std::string sentence;                 // the whole sentence the reports print
};

// The findings for the failing categories of a graded run: `expected`, `results` (the candidate's
// outputs in the contract's order, as graded: already rounded to the dtype, as make_report keeps them)
// and `outcomes` index-aligned; `stencil` the order the candidate declared. Findings that explain several
// categories are merged (one sentence listing them).
std::vector<Finding> diagnose(const std::vector<Expected>& expected, const std::vector<CandidateResult>& results,
                              const std::vector<CaseOutcome>& outcomes, const Grading& grading, const Stencil& stencil);

}  // namespace hinge::conformance
