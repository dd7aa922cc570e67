// The autodiff baseline instantiated for float, double, long double: one unit per scalar family and method, so that
// no unit compiles more than one family of these heavy templates.
#include "autodiff_impl.hpp"

HINGE_AUTODIFF_INSTANTIATE(float)
HINGE_AUTODIFF_INSTANTIATE(double)
HINGE_AUTODIFF_INSTANTIATE(long double)
