// The baseline methods (src/baselines.hpp) for mpfr.
#include "baselines_impl.hpp"

HINGE_METHODS_BASELINE_INSTANTIATE(hinge::mpfr)
