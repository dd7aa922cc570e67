// The baseline methods (src/baselines.hpp) for float128 and bin128.
#include "baselines_impl.hpp"

HINGE_METHODS_BASELINE_INSTANTIATE(hinge::float128)
HINGE_METHODS_BASELINE_INSTANTIATE(hinge::bin128)
