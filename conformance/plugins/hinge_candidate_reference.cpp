// The project's reference per-hinge kernel as a conformance plugin (hinge/candidate.h):
// hinge::reference::theta_derivatives<double>. Built as the module hinge_candidate_reference; ctest
// (label conformance) runs it through `hinge conform --plugin` and expects a pass.
#include "candidate_adapter.hpp"
#include "hinge/reference/evaluate.hpp"

extern "C" int hinge_candidate(const double x[12], double* theta, double grad[12], double hess[144]) {
  return hinge::plugins::call_candidate(
      x, theta, grad, hess,
      [](const std::array<double, 12>& in) { return hinge::reference::theta_derivatives<double>(in, true); },
      [](const auto& d) { return d.angle.theta; });
}
