// A bending term whose weight misses its 3 (w = |e_bar|^2 / A_bar, a slip simulators make): its energy,
// gradient and Hessian are 1/3 of the contract's everywhere. Consistent in itself, it fails against the
// certified values, and the diagnosis names the factor 1/3.
#include "energy_term.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_energy_candidate(const double x[12], const double rest[12], double* energy,
                                                             double grad[12], double hess[144]) {
  return candidates::tan_term(x, rest, 1.0 / 3, energy, grad, hess) ? 0 : 1;
}
