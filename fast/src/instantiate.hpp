// What the generated instantiation units (hinge_scalar_units in fast/CMakeLists.txt, one per scalar family)
// instantiate for each scalar type: the per-hinge kernel and the assembler. (double's vector kernel itself:
// hinge_kernel_double.cpp.)
#pragma once

#include "assembler_impl.hpp"
#include "hinge_kernel_impl.hpp"

#define HINGE_FAST_INSTANTIATE(S) \
  HINGE_FAST_HINGE_INSTANTIATE(S) \
  template class hinge::fast::Assembler<S>;
