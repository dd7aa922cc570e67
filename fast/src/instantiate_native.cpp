// Explicit instantiations of hinge::fast for float and double (double's per-hinge kernel itself:
// hinge_kernel_double.cpp). One unit per scalar family keeps builds short on two cores.
#include "assembler_impl.hpp"
#include "hinge_kernel_impl.hpp"

HINGE_FAST_HINGE_INSTANTIATE(float)
HINGE_FAST_HINGE_INSTANTIATE(double)

template class hinge::fast::Assembler<float>;
template class hinge::fast::Assembler<double>;
