// Definitions of src/baselines.hpp's templates, for the units baselines_*.cpp.
#pragma once

#include <string>

#include "baselines.hpp"
#include "hinge/baselines/autodiff.hpp"
#include "hinge/baselines/symbolic.hpp"
#include "hinge/reference/assemble_impl.hpp"
#include "hinge/reference/rounded.hpp"

namespace hinge::methods::detail {

// theta, grad theta, Hess theta (as requested) by the baseline `method` in Scalar. A NaN or an infinity
// is a DomainError that says so: the baselines do not rescale, so an intermediate may overflow or
// underflow where the other methods' do not.
template <HingeScalar Scalar>
baselines::Derivatives<Scalar> baseline_derivatives(Method method, const std::array<double, 12>& x, bool with_hessian) {
  const auto outputs = with_hessian ? baselines::Outputs::hessian : baselines::Outputs::gradient;
  baselines::Derivatives<Scalar> d = method == Method::autodiff ? baselines::autodiff_derivatives<Scalar>(x, outputs)
                                                                : baselines::symbolic_derivatives<Scalar>(x, outputs);
  using std::isfinite;
  bool finite = isfinite(d.theta);
  for (const auto& g : d.grad) finite = finite && isfinite(g);
  for (const auto& h : d.hess.reshaped()) finite = finite && isfinite(h);
  if (!finite)
    throw DomainError(std::string(method_name(method)) + " in " + scalar_name<Scalar>() +
                      " gave a NaN or an infinity (the method does not rescale: an intermediate overflowed or "
                      "underflowed)");
  return d;
}

template <HingeScalar Scalar>
reference::RoundedTheta baseline_hinge(Method method, const std::array<double, 12>& x) {
  const baselines::Derivatives<Scalar> d = baseline_derivatives<Scalar>(method, x, true);
  return reference::round_theta(d.theta, d.grad, d.hess);
}

template <HingeScalar Scalar>
reference::RoundedMesh baseline_mesh(Method method, const MeshInput& in) {
  const auto coefficients = reference::rest_state<Scalar>(*in.rest, *in.topology, in.parameters);  // Algorithm 1
  const auto theta_of = [method](const std::array<double, 12>& x, bool with_hessian) {
    const baselines::Derivatives<Scalar> d = baseline_derivatives<Scalar>(method, x, with_hessian);
    reference::ThetaDerivatives<Scalar> t;
    t.angle.theta = d.theta;
    using std::tan;
    t.angle.tan_half_theta = tan(d.theta / 2);  // what a user of these methods computes for phi (eq. (8))
    t.angle.on_branch_cut = d.theta == pi_of<Scalar>();
    t.grad = d.grad;
    t.hess = d.hess;
    return t;
  };
  return reference::round_mesh(
      reference::assemble_with<Scalar>(*in.deformed, *in.topology, coefficients, in.parameters.model, in.request, theta_of),
      in.request);
}

}  // namespace hinge::methods::detail

#define HINGE_METHODS_BASELINE_INSTANTIATE(S)                                                                 \
  template hinge::reference::RoundedTheta hinge::methods::detail::baseline_hinge<S>(hinge::methods::Method,   \
                                                                                    const std::array<double, 12>&); \
  template hinge::reference::RoundedMesh hinge::methods::detail::baseline_mesh<S>(hinge::methods::Method,     \
                                                                                  const hinge::methods::MeshInput&);
