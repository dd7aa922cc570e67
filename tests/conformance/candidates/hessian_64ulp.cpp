// A deliberately wrong candidate: every nonzero Hessian entry 64 ulps away from zero (a relative error
// between 64 and 128 units of 2^-53); theta and the gradient are right. `hinge conform` must reject it
// on the well-conditioned cases, where the tolerance is below 64 units.
#include <cmath>

#include "reference_double.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12],
                                                      double hess[144]) {
  if (!candidates::reference_double(x, theta, grad, hess)) return 1;
  for (int i = 0; i < 144; ++i)
    for (int k = 0; k < 64 && hess[i] != 0; ++k) hess[i] = std::nextafter(hess[i], 2 * hess[i]);
  return 0;
}
