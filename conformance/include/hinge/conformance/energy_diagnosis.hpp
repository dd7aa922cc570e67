// hinge/conformance/energy_diagnosis.hpp: why a bending term fails (docs/energy-conformance.md, "Diagnosis"):
// the usual mistakes above theta's derivatives, each tried as a prediction of what a term with that mistake
// returns: a Gauss-Newton Hessian given where the exact one was declared, and the other way; the rest angle
// ignored (theta_bar = 0: a force at rest), negated, in degrees, or off by 2 pi ([0, 2 pi) or (-2 pi, 0]);
// the energy off by a constant factor p/q (p, q <= 12) or (180/pi)^(+-1, +-2) on every hinge, or by a
// factor of the rest hinge: |e_bar|^(+-1), |e_bar|^2, A_bar^(+-1), an altitude h0 or h3 (or its inverse).
// Named as the theta kit's (diagnosis.hpp): where it lifts a failing category to at least `approximate`,
// changes a case beyond its tolerance and makes no other category fail.
#pragma once

#include <vector>

#include "hinge/conformance/diagnosis.hpp"
#include "hinge/conformance/energy_expected.hpp"

namespace hinge::conformance {

// `expected` (with input.rest), `results` (as graded) and `outcomes` index-aligned; `weights` the weight w
// of each case's term (as the expectations used it); `diagonal_blocks` as graded.
std::vector<Finding> diagnose_energy(const std::vector<Expected>& expected, const std::vector<CandidateResult>& results,
                                     const std::vector<CaseOutcome>& outcomes, const Grading& grading,
                                     const EnergyProblem& problem, const std::vector<double>& weights,
                                     bool diagonal_blocks);

}  // namespace hinge::conformance
