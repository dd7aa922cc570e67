// The symbolic baseline instantiated for QD's dd and qd: one unit per scalar family and method, so that
// no unit compiles more than one family of these heavy templates.
#include "symbolic_impl.hpp"

HINGE_SYMBOLIC_INSTANTIATE(hinge::dd)
HINGE_SYMBOLIC_INSTANTIATE(hinge::qd)
