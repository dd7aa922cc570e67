// The project's fast per-hinge kernel as a conformance plugin (hinge/candidate.h):
// hinge::fast::hinge_derivatives<double>, checked by `hinge conform --plugin` exactly as an outside
// implementation would be (ctest conform_plugin_fast, label conformance), and loadable by outside
// benchmarks beside other implementations.
#include "candidate_adapter.hpp"
#include "hinge/fast/hinge_kernel.hpp"

extern "C" int hinge_candidate(const double x[12], double* theta, double grad[12], double hess[144]) {
  // Straight into the caller's arrays (hinge::fast::hinge_derivatives_into): no intermediate matrix.
  return hinge::plugins::call_candidate_into(
      x, [&](const std::array<double, 12>& in) { hinge::fast::hinge_derivatives_into(in, *theta, grad, hess); });
}
