// Explicit instantiations of hinge::fast for mpfr (run-time precision).
#include "assembler_impl.hpp"
#include "hinge_kernel_impl.hpp"

HINGE_FAST_HINGE_INSTANTIATE(hinge::mpfr)

template class hinge::fast::Assembler<hinge::mpfr>;
