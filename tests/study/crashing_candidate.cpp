// A candidate (hinge/candidate.h) that crashes on every hinge whose x0.x is above 0.5 and returns zeros
// elsewhere: the study must count those hinges failed, name the crash, and go on (study_test.cpp).
#include <cstdlib>

#include "hinge/candidate.h"

int hinge_candidate(const double x[12], double* theta, double grad[12], double hess[144]) {
  if (x[0] > 0.5) std::abort();
  *theta = 0;
  for (int i = 0; i < 12; ++i) grad[i] = 0;
  for (int i = 0; i < 144; ++i) hess[i] = 0;
  return 0;
}
