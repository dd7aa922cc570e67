// The baseline methods (autodiff, symbolic: hinge::baselines) behind hinge::methods: one hinge rounded to
// double, and a whole mesh assembled hinge by hinge with the reference's assembly (eqs. (1)-(3)) around
// the baseline's theta, gradient and Hessian. Instantiated per scalar family (baselines_*.cpp), so that
// methods.cpp compiles none of the multiprecision templates.
#pragma once

#include <array>

#include "hinge/methods/methods.hpp"
#include "hinge/reference/results.hpp"

namespace hinge::methods::detail {

template <HingeScalar Scalar>
reference::RoundedTheta baseline_hinge(Method method, const std::array<double, 12>& x);
template <HingeScalar Scalar>
reference::RoundedMesh baseline_mesh(Method method, const MeshInput& input);

#define HINGE_METHODS_BASELINE_EXTERN(S)                                                                 \
  extern template reference::RoundedTheta baseline_hinge<S>(Method, const std::array<double, 12>&);       \
  extern template reference::RoundedMesh baseline_mesh<S>(Method, const MeshInput&);
HINGE_FOR_EACH_SCALAR(HINGE_METHODS_BASELINE_EXTERN)
#undef HINGE_METHODS_BASELINE_EXTERN

}  // namespace hinge::methods::detail
