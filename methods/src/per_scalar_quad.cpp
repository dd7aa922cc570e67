// hinge::methods per scalar type (src/per_scalar.hpp) for float128 and bin128.
#include "per_scalar_impl.hpp"

HINGE_METHODS_PER_SCALAR_INSTANTIATE(hinge::float128)
HINGE_METHODS_PER_SCALAR_INSTANTIATE(hinge::bin128)
