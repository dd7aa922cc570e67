// Explicit instantiations of hinge::fast for long double, float128 and bin128.
#include "assembler_impl.hpp"
#include "hinge_kernel_impl.hpp"

HINGE_FAST_HINGE_INSTANTIATE(long double)
HINGE_FAST_HINGE_INSTANTIATE(hinge::float128)
HINGE_FAST_HINGE_INSTANTIATE(hinge::bin128)

template class hinge::fast::Assembler<long double>;
template class hinge::fast::Assembler<hinge::float128>;
template class hinge::fast::Assembler<hinge::bin128>;
