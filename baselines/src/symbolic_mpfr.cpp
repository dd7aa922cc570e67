// The symbolic baseline instantiated for mpfr (run-time precision): one unit per scalar family and method, so that
// no unit compiles more than one family of these heavy templates.
#include "symbolic_impl.hpp"

HINGE_SYMBOLIC_INSTANTIATE(hinge::mpfr)
