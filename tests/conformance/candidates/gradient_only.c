/* A candidate written in C against hinge/candidate.h: theta (docs/contract.md) and its gradient (eq. (4))
 * in plain double, the Hessian left zero. It shows the C interface; `hinge conform` must pass its theta
 * and gradient and reject it for the Hessian.
 *
 *                 x0
 *               /  \          e0 = x2 - x1, e1 = x0 - x2, e2 = x1 - x0 (upper triangle)
 *             x1 -> x2        et1 = x3 - x2, et2 = x1 - x3 (lower triangle)
 *               \  /          variables: x0, x1, x2, x3 (12)
 *                x3
 */
#include <math.h>

#include "hinge/candidate.h"

static void sub(const double* a, const double* b, double* r) {
  int c;
  for (c = 0; c < 3; ++c) r[c] = a[c] - b[c];
}
static void cross(const double* a, const double* b, double* r) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
static double dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12], double hess[144]) {
  double e0[3], e1[3], e2[3], et1[3], et2[3], N[3], Nt[3], NxNt[3];
  double nn, tt, l0, y;
  int i, c;
  sub(x + 6, x + 3, e0);
  sub(x + 0, x + 6, e1);
  sub(x + 3, x + 0, e2);
  sub(x + 9, x + 6, et1);
  sub(x + 3, x + 9, et2);
  /* N = (x1 - x0) x (x2 - x0) = e2 x e0 and Nt = (x2 - x3) x (x1 - x3) = e0 x et2: products with the
     hinge edge keep N and Nt accurately perpendicular to it, even when it is short. */
  cross(e2, e0, N);
  cross(e0, et2, Nt);
  nn = dot(N, N);
  tt = dot(Nt, Nt);
  l0 = sqrt(dot(e0, e0));
  if (nn == 0 || tt == 0 || l0 == 0) return 1;
  cross(N, Nt, NxNt);
  y = dot(NxNt, e0) / l0;
  *theta = atan2(y == 0 ? 0.0 : y, dot(N, Nt)); /* +0: the branch cut gives +pi */
  for (c = 0; c < 3; ++c) { /* eq. (4), with h0 = |N| / l0, cos(alpha2) / h1 = -(e0 . e1) / (l0 |N|), ... */
    grad[0 + c] = -l0 * N[c] / nn;
    grad[3 + c] = -(dot(e0, e1) * N[c] / nn + dot(e0, et1) * Nt[c] / tt) / l0;
    grad[6 + c] = -(dot(e0, e2) * N[c] / nn + dot(e0, et2) * Nt[c] / tt) / l0;
    grad[9 + c] = -l0 * Nt[c] / tt;
  }
  for (i = 0; i < 144; ++i) hess[i] = 0;
  return 0;
}
