// A deliberately wrong candidate: the gradient of x3 with the wrong sign (grad_x3 = +n~ / h~0 instead of
// -n~ / h~0, eq. (4)); theta and the Hessian are right. `hinge conform` must reject it.
#include "reference_double.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12],
                                                      double hess[144]) {
  if (!candidates::reference_double(x, theta, grad, hess)) return 1;
  for (int i = 9; i < 12; ++i) grad[i] = -grad[i];
  return 0;
}
