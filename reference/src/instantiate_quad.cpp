// Explicit instantiations of hinge::reference for float128 and bin128 (cpp_bin_float_quad). One unit per scalar family keeps
// the heavy multiprecision templates out of every other unit (their headers declare them extern).
#include "hinge/reference/assemble_impl.hpp"

HINGE_REFERENCE_INSTANTIATE(hinge::float128)
HINGE_REFERENCE_INSTANTIATE(hinge::bin128)
