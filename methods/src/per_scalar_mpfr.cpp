// hinge::methods per scalar type (src/per_scalar.hpp) for mpfr.
#include "per_scalar_impl.hpp"

HINGE_METHODS_PER_SCALAR_INSTANTIATE(hinge::mpfr)
