// The symbolic baseline instantiated for float128 and bin128: one unit per scalar family and method, so that
// no unit compiles more than one family of these heavy templates.
#include "symbolic_impl.hpp"

HINGE_SYMBOLIC_INSTANTIATE(hinge::float128)
HINGE_SYMBOLIC_INSTANTIATE(hinge::bin128)
