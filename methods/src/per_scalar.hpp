// What hinge::methods does per scalar type, behind the run-time choice: the baselines' hinge (autodiff,
// symbolic: hinge::baselines) rounded to double, and the prepared mesh evaluations of every method
// (MeshEvaluator's implementations). Instantiated per scalar family (per_scalar_*.cpp), so that
// methods.cpp compiles none of the multiprecision templates.
#pragma once

#include <array>
#include <memory>

#include "hinge/core/results.hpp"
#include "hinge/methods/methods.hpp"

namespace hinge::methods::detail {

template <HingeScalar Scalar>
RoundedTheta baseline_hinge(Method method, const std::array<double, 12>& x);

// MeshEvaluator's implementation in one scalar type.
struct EvaluatorImpl {
  virtual ~EvaluatorImpl() = default;
  virtual void evaluate(bool last) = 0;
  virtual RoundedMesh take_result() = 0;
};
template <HingeScalar Scalar>
std::unique_ptr<EvaluatorImpl> make_evaluator(Method method, const MeshInput& input);

#define HINGE_METHODS_PER_SCALAR_EXTERN(S)                                               \
  extern template RoundedTheta baseline_hinge<S>(Method, const std::array<double, 12>&); \
  extern template std::unique_ptr<EvaluatorImpl> make_evaluator<S>(Method, const MeshInput&);
HINGE_FOR_EACH_SCALAR(HINGE_METHODS_PER_SCALAR_EXTERN)
#undef HINGE_METHODS_PER_SCALAR_EXTERN

}  // namespace hinge::methods::detail
