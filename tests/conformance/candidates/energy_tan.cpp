// A correct bending term (energy_term.hpp): the tan energy with the contract's weight, k = 1. Passes
// `hinge conform --energy tan --plugin`.
#include "energy_term.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_energy_candidate(const double x[12], const double rest[12], double* energy,
                                                             double grad[12], double hess[144]) {
  return candidates::tan_term(x, rest, 1.0, energy, grad, hess) ? 0 : 1;
}
