// Explicit instantiations of hinge::fast for QD's dd and qd.
#include "assembler_impl.hpp"
#include "hinge_kernel_impl.hpp"

HINGE_FAST_HINGE_INSTANTIATE(hinge::dd)
HINGE_FAST_HINGE_INSTANTIATE(hinge::qd)

template class hinge::fast::Assembler<hinge::dd>;
template class hinge::fast::Assembler<hinge::qd>;
