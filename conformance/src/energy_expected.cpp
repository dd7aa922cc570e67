// What a bending term must give on an energy case (hinge/conformance/energy_expected.hpp).
#include "hinge/conformance/energy_expected.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hinge/conformance/energy_sets.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/oracle/conditioning.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge/oracle/projected.hpp"
#include "hinge/oracle/quadratic.hpp"

namespace hinge::conformance {
namespace {

// |psi''(theta_bar)| in double, with the weight (the contract's computed from R in double): a tolerance needs a
// digit of it, not more.
double psi_second_at_rest(const std::array<double, 12>& rest, const EnergyProblem& p, double theta_bar,
                          std::optional<double> weight) {
  HingeCoefficients<double> c;
  c.k = p.k;
  c.a = weight ? *weight : named_weight("contract", rest);  // Algorithm 1
  if (p.quadratic) return 2 * p.k * c.a;                    // as shells: k a theta^2 to leading order
  c.theta_bar = theta_bar;
  c.phi_bar = 2 * std::tan(theta_bar / 2);
  const BendAngle<double> b{theta_bar, std::tan(theta_bar / 2), false};
  return std::fabs(psi(p.model, c, b).d2);
}

}  // namespace

std::string energy_name(const EnergyProblem& problem) {
  return problem.quadratic ? "quadratic" : std::string(model_name(problem.model));
}

Expected energy_expected(const EnergyCase& c, const EnergyProblem& problem, bool conditioning,
                         std::optional<double> weight) {
  if (problem.quadratic) {
    if (weight || problem.hessian != HessianKind::exact)
      throw std::invalid_argument("the quadratic energy takes no weight and has one Hessian (exact)");
    const oracle::CertifiedEnergy q = oracle::certified_quadratic(c.x, c.rest, problem.k);
    Expected e;
    e.input = {c.id, c.category, c.x, c.rest};
    e.values.theta = q.energy;
    e.values.grad = q.grad;
    e.values.hess = q.hess;
    e.values.bits = q.bits;
    e.values.uncertified = q.uncertified;
    if (!conditioning) return e;
    e.conditioning = oracle::quadratic_conditioning(c.x, c.rest, problem.k, q.energy, q.grad, q.hess);
    apply_zero_energy_bound(e, c, problem, weight);
    return e;
  }
  const Mesh x = hinge_mesh(c.x), rest = hinge_mesh(c.rest);
  EnergyParameters parameters;
  parameters.model = problem.model;
  parameters.k = problem.k;
  oracle::Options options;
  options.gauss_newton = problem.hessian == HessianKind::gauss_newton;
  if (weight) options.weights = {*weight};
  const oracle::CertifiedMesh m = oracle::certified_mesh(x, rest, build_topology(x), parameters, want_all, options);
  Expected e;
  e.input = {c.id, c.category, c.x, c.rest};
  e.values.theta = m.rounded.energy;
  for (int i = 0; i < 12; ++i) e.values.grad[i] = m.rounded.gradient[static_cast<std::size_t>(i)];
  for (Eigen::Index col = 0; col < m.rounded.hessian.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m.rounded.hessian, col); it; ++it) {
      e.values.hess[static_cast<std::size_t>(12 * it.row() + it.col())] = it.value();
      e.values.hess[static_cast<std::size_t>(12 * it.col() + it.row())] = it.value();
    }
  e.values.uncertified = m.uncertified;
  std::array<double, 144> exact_hessian = e.values.hess;
  if (problem.hessian == HessianKind::projected) {
    EnergyParameters unit = parameters;  // the 256-bit reference for k = 1 and the contract's weight, scaled: a
    unit.k = 1;                          // positive factor commutes with the projection
    e.values.hess = oracle::projected_hessian_256(c.x, c.rest, unit);
    const double factor = problem.k * (weight ? *weight / named_weight("contract", c.rest) : 1.0);
    for (double& v : e.values.hess) v *= factor;
  }
  if (!conditioning) return e;
  e.conditioning = oracle::energy_conditioning(c.x, c.rest, parameters, options.gauss_newton, e.values.theta,
                                               e.values.grad, exact_hessian);
  if (problem.hessian == HessianKind::projected) set_projected_kappa(e);
  apply_zero_energy_bound(e, c, problem, weight);
  return e;
}

void set_projected_kappa(Expected& e) {
  const double size = oracle::scaled_norm(e.values.hess.data(), 144);  // ||H_+||; scale[2] = kappa_H ||H||
  e.conditioning.kappa[2] = size > 0 ? e.conditioning.scale[2] / size : 1.0;
}

const char* hessian_kind_name(HessianKind h) {
  switch (h) {
    case HessianKind::exact: return "exact";
    case HessianKind::gauss_newton: return "gauss-newton";
    case HessianKind::projected: return "projected";
  }
  return "?";
}

void apply_zero_energy_bound(Expected& e, const EnergyCase& c, const EnergyProblem& problem,
                             std::optional<double> weight, Dtype dtype) {
  if (e.values.theta != 0) return;
  const oracle::CertifiedTheta tx = oracle::certified_theta_derivatives(c.x);
  const oracle::CertifiedTheta tr = oracle::certified_theta_derivatives(c.rest);
  const double L = e.conditioning.length;
  const double s = L * (oracle::scaled_norm(tx.grad.data(), 12) + oracle::scaled_norm(tr.grad.data(), 12));
  const double u = unit_roundoff(dtype);
  const double bound = psi_second_at_rest(c.rest, problem, tr.theta, weight) * (16 * u * s) * (16 * u * s) / 2;
  const Policy policy;
  e.conditioning.scale[0] = bound / ((policy.base + policy.c * 1) * u);  // error <= tolerance iff |psi| <= bound
  e.conditioning.kappa[0] = 1;
}

}  // namespace hinge::conformance
