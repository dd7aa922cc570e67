// Definitions of src/per_scalar.hpp's templates, for the units per_scalar_*.cpp.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hinge/baselines/derivatives.hpp"
#include "hinge/core/rounding.hpp"
#include "hinge/fast/assemble.hpp"
#include "hinge/reference/assemble_impl.hpp"
#include "per_scalar.hpp"

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
RoundedTheta baseline_hinge(Method method, const std::array<double, 12>& x) {
  const baselines::Derivatives<Scalar> d = baseline_derivatives<Scalar>(method, x, true);
  return round_theta(d.theta, d.grad, d.hess);
}

// The reference and the baselines: Algorithm 1 once, then the reference's hinge-by-hinge assembly
// (eqs. (1)-(3)) around the method's theta, gradient and Hessian.
template <HingeScalar Scalar>
class HingeByHinge final : public EvaluatorImpl {
 public:
  HingeByHinge(Method method, const MeshInput& in)
      : method_(method), in_(in), coefficients_(reference::rest_state<Scalar>(*in.rest, *in.topology, in.parameters)) {}

  void evaluate(bool) override {
    const Model model = in_.parameters.model;
    if (method_ == Method::reference) {
      out_ = reference::assemble<Scalar>(*in_.deformed, *in_.topology, coefficients_, model, in_.request);
      return;
    }
    const Method method = method_;
    out_ = reference::assemble_with<Scalar>(*in_.deformed, *in_.topology, coefficients_, model, in_.request,
                                            [method](const std::array<double, 12>& x, bool with_hessian) {
                                              const auto d = baseline_derivatives<Scalar>(method, x, with_hessian);
                                              reference::ThetaDerivatives<Scalar> t;
                                              t.angle.theta = d.theta;
                                              using std::tan;
                                              t.angle.tan_half_theta = tan(d.theta / 2);  // for phi, eq. (8)
                                              t.angle.on_branch_cut = d.theta == pi_of<Scalar>();
                                              t.grad = d.grad;
                                              t.hess = d.hess;
                                              return t;
                                            });
  }
  RoundedMesh take_result() override { return round_mesh(std::move(out_), in_.request); }

 private:
  Method method_;
  MeshInput in_;
  std::vector<HingeCoefficients<Scalar>> coefficients_;
  MeshDerivatives<Scalar> out_;
};

// fast: Algorithm 1 and the pattern once (hinge::fast::Assembler), then Algorithm 2. The last evaluation
// consumes the per-hinge constants (freed before the Hessian is allocated) and frees the pattern and the
// work arrays before the result is rounded: the peak memory of a one-off `hinge hessian`.
template <HingeScalar Scalar>
class Fast final : public EvaluatorImpl {
 public:
  explicit Fast(const MeshInput& in) : in_(in) {
    assembler_.emplace(*in.topology);
    coefficients_ = assembler_->rest_state(*in.rest, in.parameters, in.threads);
  }

  void evaluate(bool last) override {
    if (!assembler_) throw std::logic_error("MeshEvaluator::evaluate after the last evaluation");
    const Model model = in_.parameters.model;
    if (last) {
      assembler_->evaluate(*in_.deformed, std::move(coefficients_), model, in_.request, in_.threads, out_);
      assembler_.reset();
    } else {
      assembler_->evaluate(*in_.deformed, coefficients_, model, in_.request, in_.threads, out_);
    }
  }
  RoundedMesh take_result() override { return round_mesh(std::move(out_), in_.request); }

 private:
  MeshInput in_;
  std::optional<fast::Assembler<Scalar>> assembler_;
  std::vector<HingeCoefficients<Scalar>> coefficients_;
  MeshDerivatives<Scalar> out_;
};

template <HingeScalar Scalar>
std::unique_ptr<EvaluatorImpl> make_evaluator(Method method, const MeshInput& input) {
  if (method == Method::fast) return std::make_unique<Fast<Scalar>>(input);
  return std::make_unique<HingeByHinge<Scalar>>(method, input);
}

}  // namespace hinge::methods::detail

#define HINGE_METHODS_PER_SCALAR_INSTANTIATE(S)                                                              \
  template hinge::RoundedTheta hinge::methods::detail::baseline_hinge<S>(hinge::methods::Method,             \
                                                                         const std::array<double, 12>&);     \
  template std::unique_ptr<hinge::methods::detail::EvaluatorImpl> hinge::methods::detail::make_evaluator<S>( \
      hinge::methods::Method, const hinge::methods::MeshInput&);
