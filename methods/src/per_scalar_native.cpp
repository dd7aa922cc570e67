// The baseline methods (src/baselines.hpp) for float, double and long double.
#include "baselines_impl.hpp"

HINGE_METHODS_BASELINE_INSTANTIATE(float)
HINGE_METHODS_BASELINE_INSTANTIATE(double)
HINGE_METHODS_BASELINE_INSTANTIATE(long double)
