// hinge::methods per scalar type (src/per_scalar.hpp) for QD's dd and qd.
#include "per_scalar_impl.hpp"

HINGE_METHODS_PER_SCALAR_INSTANTIATE(hinge::dd)
HINGE_METHODS_PER_SCALAR_INSTANTIATE(hinge::qd)
