// A deliberately wrong candidate: derivatives by central differences with a fixed step h = 1e-6 (not
// scaled with the hinge): the gradient from theta, the Hessian from the gradient of the reference in
// double. Truncation and cancellation errors of about 1e-10 relative on unit hinges, and nonsense on
// small ones. `hinge conform --plugin` must reject it.
#include "reference_double.hpp"

namespace {
constexpr double h = 1e-6;
}

extern "C" HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12],
                                                      double hess[144]) {
  double g[12], H[144];
  if (!candidates::reference_double(x, theta, g, H)) return 1;
  for (int j = 0; j < 12; ++j) {
    double xp[12], xm[12], tp, tm, gp[12], gm[12];
    for (int i = 0; i < 12; ++i) xp[i] = xm[i] = x[i];
    xp[j] += h;
    xm[j] -= h;
    if (!candidates::reference_double(xp, &tp, gp, H) || !candidates::reference_double(xm, &tm, gm, H)) return 1;
    grad[j] = (tp - tm) / (2 * h);
    for (int i = 0; i < 12; ++i) hess[12 * i + j] = (gp[i] - gm[i]) / (2 * h);
  }
  return 0;
}
