// conformance/src/diagnosis_engine.hpp (private to hinge::conformance): the diagnosis's engine, shared by the
// theta kit's conventions (diagnosis.cpp) and the bending energies' (energy_diagnosis.cpp). A hypothesis
// gives, for each case, the outputs graded in its place; it is named for a failing category when, applied to
// every evaluated case of it, it lifts the category to at least `approximate` and changes a case beyond its
// tolerance, and it makes no category fail that does not fail now (docs/conformance.md, "Diagnosis").
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "hinge/conformance/diagnosis.hpp"

namespace hinge::conformance::detail {

// A case's three output groups (theta or psi, gradient, Hessian), the contract's order.
struct Outputs {
  double theta = 0;
  std::array<double, 12> grad{};
  std::array<double, 144> hess{};
};
inline Outputs outputs_of(const CertifiedTheta& v) { return {v.theta, v.grad, v.hess}; }
inline Outputs outputs_of(const CandidateResult& r) { return {r.theta, r.grad, r.hess}; }

// A hypothesis: for case i (of the expected, results arrays) the outputs graded in its place, or nothing
// when it cannot be applied (the permuted hinge is degenerate).
struct Hypothesis {
  std::string key, explanation, change;
  bool forward = true;  // predicts the expected values (true) or repairs the candidate's (false)
  std::function<std::optional<Outputs>(std::size_t)> apply;
  std::array<bool, 3> changes{true, true, true};  // the output groups it can change (theta, grad, hess)
  // A variant of the hypothesis before it that differs from it only in these groups: tried only where one of
  // them was given (else the two are one hypothesis, named once as the earlier).
  std::array<bool, 3> differs{true, true, true};
};

// The findings of `hypotheses` (tried in order: simplest first) on the failing categories of a graded run.
std::vector<Finding> explain_failures(std::vector<Hypothesis> hypotheses, const std::vector<Expected>& expected,
                                      const std::vector<CandidateResult>& results,
                                      const std::vector<CaseOutcome>& outcomes, const Grading& grading);

}  // namespace hinge::conformance::detail
