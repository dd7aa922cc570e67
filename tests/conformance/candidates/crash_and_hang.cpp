// A candidate that hinge conform must survive (docs/contract.md, "Plugins"): right on most hinges (the
// reference in double), it dereferences a null pointer on the hinges far above unit size (a coordinate
// beyond 1e100: in the scales category) and never returns on those far below it (every nonzero coordinate
// below 1e-100 in magnitude).
#include <cmath>

#include "reference_double.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12],
                                                      double hess[144]) {
  double largest = 0;
  for (int i = 0; i < 12; ++i) largest = std::fmax(largest, std::fabs(x[i]));
  if (largest > 1e100) {
    volatile int* null = nullptr;
    *null = 1;  // SIGSEGV
  }
  if (largest < 1e-100)
    for (volatile bool forever = true; forever;) {
    }
  return candidates::reference_double(x, theta, grad, hess) ? 0 : 1;
}
