// The project's fast per-hinge kernel as a conformance plugin (hinge/candidate.h):
// hinge::fast::hinge_derivatives<double>, checked by `hinge conform --plugin` exactly as an outside
// implementation would be (ctest conform_plugin_fast, label conformance), and loadable by outside
// benchmarks beside other implementations.
#include "candidate_adapter.hpp"
#include "hinge/fast/hinge_kernel.hpp"

extern "C" int hinge_candidate(const double x[12], double* theta, double grad[12], double hess[144]) {
  return hinge::plugins::call_candidate(
      x, theta, grad, hess, [](const std::array<double, 12>& in) { return hinge::fast::hinge_derivatives<double>(in, true); },
      [](const auto& d) { return d.theta; });
}
