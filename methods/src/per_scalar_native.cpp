// hinge::methods per scalar type (src/per_scalar.hpp) for float, double and long double.
#include "per_scalar_impl.hpp"

HINGE_METHODS_PER_SCALAR_INSTANTIATE(float)
HINGE_METHODS_PER_SCALAR_INSTANTIATE(double)
HINGE_METHODS_PER_SCALAR_INSTANTIATE(long double)
