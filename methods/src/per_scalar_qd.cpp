// The baseline methods (src/baselines.hpp) for QD's dd and qd.
#include "baselines_impl.hpp"

HINGE_METHODS_BASELINE_INSTANTIATE(hinge::dd)
HINGE_METHODS_BASELINE_INSTANTIATE(hinge::qd)
