// The evaluation methods by name (hinge/methods/methods.hpp).
#include "hinge/methods/methods.hpp"

#include <stdexcept>

#include "hinge/fast/rounded.hpp"
#include "hinge/reference/rounded.hpp"
#include "per_scalar.hpp"

namespace hinge::methods {

RoundedTheta evaluate_hinge(Method method, const ScalarType& scalar, const std::array<double, 12>& x) {
  switch (method) {
    case Method::reference: return reference::theta_derivatives_rounded(scalar, x);
    case Method::fast: return fast::hinge_derivatives_rounded(scalar, x);
    case Method::autodiff:
    case Method::symbolic:
      return visit_scalar_type(scalar, [&]<class Scalar>() { return detail::baseline_hinge<Scalar>(method, x); });
  }
  throw std::invalid_argument("evaluate_hinge: unknown method");
}

MeshEvaluator::MeshEvaluator(Method method, const ScalarType& scalar, const MeshInput& input)
    : scalar_(scalar),
      impl_(visit_scalar_type(scalar, [&]<class Scalar>() { return detail::make_evaluator<Scalar>(method, input); })) {}
MeshEvaluator::~MeshEvaluator() = default;
MeshEvaluator::MeshEvaluator(MeshEvaluator&&) noexcept = default;
MeshEvaluator& MeshEvaluator::operator=(MeshEvaluator&&) noexcept = default;

void MeshEvaluator::evaluate(bool last) {
  if (scalar_.kind == ScalarType::Kind::kind_mpfr) set_mpfr_bits(scalar_.mpfr_bits);
  impl_->evaluate(last);
}

RoundedMesh MeshEvaluator::take_result() {
  if (scalar_.kind == ScalarType::Kind::kind_mpfr) set_mpfr_bits(scalar_.mpfr_bits);
  return impl_->take_result();
}

RoundedMesh evaluate_mesh(Method method, const ScalarType& scalar, const MeshInput& in) {
  MeshEvaluator evaluator(method, scalar, in);
  evaluator.evaluate(true);
  return evaluator.take_result();
}

}  // namespace hinge::methods
