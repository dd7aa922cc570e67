// Explicit instantiations of hinge::reference for mpfr (run-time precision). One unit per scalar family keeps
// the heavy multiprecision templates out of every other unit (their headers declare them extern).
#include "hinge/reference/assemble_impl.hpp"

HINGE_REFERENCE_INSTANTIATE(hinge::mpfr)
