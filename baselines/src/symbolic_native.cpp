// The symbolic baseline instantiated for float, double, long double: one unit per scalar family and method, so that
// no unit compiles more than one family of these heavy templates.
#include "symbolic_impl.hpp"

HINGE_SYMBOLIC_INSTANTIATE(float)
HINGE_SYMBOLIC_INSTANTIATE(double)
HINGE_SYMBOLIC_INSTANTIATE(long double)
