// hinge/core/rounding.hpp: results in any scalar type rounded to the nearest double, with the errors of
// docs/contract.md where a result does not fit (never a silent infinity). Every evaluator that hands doubles
// to the commands and bindings (the reference and hinge::fast in a run-time scalar type, the faithful mode)
// rounds through these.
#pragma once

#include <Eigen/SparseCore>
#include <cmath>
#include <type_traits>

#include "hinge/core/errors.hpp"
#include "hinge/core/results.hpp"
#include "hinge/core/scalar.hpp"

namespace hinge {

// `value` rounded to the nearest double; DomainError ("<what> is outside the range of double") when
// that is not finite, or "<what> overflowed in float (...)" when `value` is a float that overflowed.
double rounded_to_double(const auto& value, const char* what) {
  const double d = to_double(value);
  if constexpr (std::is_same_v<std::remove_cvref_t<decltype(value)>, float>)
    if (!std::isfinite(d)) throw_outside_float(what);
  if (!std::isfinite(d)) throw_outside_double(what);
  return d;
}

// theta, grad theta (12) and Hess theta (12 x 12, any matrix with hess(i, j)) rounded to double.
template <class Scalar, class Grad, class Hess>
RoundedTheta round_theta(const Scalar& theta, const Grad& grad, const Hess& hess) {
  RoundedTheta r;
  r.theta = rounded_to_double(theta, "theta");
  for (int i = 0; i < 12; ++i) r.grad[i] = rounded_to_double(grad[i], "the gradient");
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) r.hess[12 * i + j] = rounded_to_double(hess(i, j), "the Hessian");
  return r;
}

// A mesh evaluation in Scalar rounded to double (the Hessian if `request` asks for it), consuming it: for
// double the Hessian is moved, not copied, and marked as an Eigen rvalue, so that assigning the result to
// another RoundedMesh swaps the matrix in (Eigen 3.4's SparseMatrix has no move assignment): assign or use
// the result, do not copy it. Throws DomainError for a result outside the range of double.
template <HingeScalar Scalar>
RoundedMesh round_mesh(MeshDerivatives<Scalar>&& m, unsigned request);
#define HINGE_ROUND_MESH_EXTERN(S) extern template RoundedMesh round_mesh<S>(MeshDerivatives<S>&&, unsigned);
HINGE_FOR_EACH_SCALAR(HINGE_ROUND_MESH_EXTERN)
#undef HINGE_ROUND_MESH_EXTERN

}  // namespace hinge
