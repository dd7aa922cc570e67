// A deliberately wrong candidate: the half-hinge bug of the paper's section 3. Computing both
// half-hinges with the left column of eq. (6), one must transpose N~0 for exactly one of them; this
// candidate forgets, so that H12 holds N0 + N~0^T instead of N0 + N~0 (and H21 its transpose). The
// difference N~0^T - N~0 is small on nearly symmetric stencils: a subtle error. `hinge conform` must
// reject it.
#include <cmath>

#include "hinge/reference/evaluate_impl.hpp"
#include "reference_double.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12],
                                                      double hess[144]) {
  if (!candidates::reference_double(x, theta, grad, hess)) return 1;
  // N~0 = n~ m~0^T / |e0|^2 (eq. (5)) from the reference's stencil, which is scaled by 2^-exponent.
  const auto p = hinge::reference::prepare_hinge<double>(candidates::input(x));
  const auto& lower = p.stencil.lower;
  const double l0 = lower.l[0];
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const double Nt0_rc = lower.n[r] * lower.m[0][c] / (l0 * l0);
      const double Nt0_cr = lower.n[c] * lower.m[0][r] / (l0 * l0);
      const double delta = std::ldexp(Nt0_cr - Nt0_rc, -2 * p.exponent);  // N~0^T - N~0, true scale
      hess[12 * (3 + r) + (6 + c)] += delta;                              // H12
      hess[12 * (6 + c) + (3 + r)] += delta;                              // H21 = H12^T
    }
  return 0;
}
