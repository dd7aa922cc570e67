// The autodiff baseline instantiated for QD's dd and qd: one unit per scalar family and method, so that
// no unit compiles more than one family of these heavy templates.
#include "autodiff_impl.hpp"

HINGE_AUTODIFF_INSTANTIATE(hinge::dd)
HINGE_AUTODIFF_INSTANTIATE(hinge::qd)
