// A bending term that hinge conform must survive: right (energy_term.hpp) except at rest, X == R exactly,
// where it dereferences a null pointer, as a term that normalizes by its distance from rest might. The
// at-rest pairs and the consistency probes at rest fail, named with the signal; the others are graded.
#include "energy_term.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_energy_candidate(const double x[12], const double rest[12], double* energy,
                                                             double grad[12], double hess[144]) {
  bool at_rest = true;
  for (int i = 0; i < 12; ++i) at_rest = at_rest && x[i] == rest[i];
  if (at_rest) {
    volatile int* null = nullptr;
    *null = 1;  // SIGSEGV
  }
  return candidates::tan_term(x, rest, 1.0, energy, grad, hess) ? 0 : 1;
}
