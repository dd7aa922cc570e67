// Explicit instantiations of hinge::reference for float, double, long double. One unit per scalar family keeps
// the heavy multiprecision templates out of every other unit (their headers declare them extern).
#include "hinge/reference/assemble_impl.hpp"

HINGE_REFERENCE_INSTANTIATE(float)
HINGE_REFERENCE_INSTANTIATE(double)
HINGE_REFERENCE_INSTANTIATE(long double)
