// What a bending term must give on an energy case (hinge/conformance/energy_expected.hpp).
#include "hinge/conformance/energy_expected.hpp"

#include <algorithm>
#include <cmath>

#include "hinge/core/mesh.hpp"
#include "hinge/oracle/conditioning.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {
namespace {

double norm3(double a, double b, double c) { return std::sqrt(a * a + b * b + c * c); }

// |psi''(theta_bar)| in double, with the contract's weight computed from R in double: a tolerance needs a
// digit of it, not more.
double psi_second_at_rest(const std::array<double, 12>& rest, const EnergyProblem& p, double theta_bar) {
  // a = 3 |e_bar|^2 / A_bar does not change with scale: coordinate differences relative to the largest one,
  // so that no square over- or underflows (the scales category reaches 2^-500 and 2^500).
  double largest = 0;
  for (int v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) largest = std::max(largest, std::fabs(rest[3 * v + c] - rest[3 + c]));
  const auto sub = [&](int a, int b, int c) { return (rest[3 * a + c] - rest[3 * b + c]) / largest; };
  const auto cross_norm = [&](int o, int a, int b) {  // |(x_a - x_o) x (x_b - x_o)|
    const double u[3] = {sub(a, o, 0), sub(a, o, 1), sub(a, o, 2)}, v[3] = {sub(b, o, 0), sub(b, o, 1), sub(b, o, 2)};
    return norm3(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
  };
  const double e = norm3(sub(2, 1, 0), sub(2, 1, 1), sub(2, 1, 2));
  const double area = (cross_norm(0, 1, 2) + cross_norm(3, 2, 1)) / 2;
  HingeCoefficients<double> c;
  c.k = p.k;
  c.a = 3 * e * e / area;  // Algorithm 1
  c.theta_bar = theta_bar;
  c.phi_bar = 2 * std::tan(theta_bar / 2);
  const BendAngle<double> b{theta_bar, std::tan(theta_bar / 2), false};
  return std::fabs(psi(p.model, c, b).d2);
}

}  // namespace

Expected energy_expected(const EnergyCase& c, const EnergyProblem& problem, bool conditioning) {
  const Mesh x = hinge_mesh(c.x), rest = hinge_mesh(c.rest);
  EnergyParameters parameters;
  parameters.model = problem.model;
  parameters.k = problem.k;
  oracle::Options options;
  options.gauss_newton = problem.hessian == HessianKind::gauss_newton;
  const oracle::CertifiedMesh m = oracle::certified_mesh(x, rest, build_topology(x), parameters, want_all, options);
  Expected e;
  e.input = {c.id, c.category, c.x};
  e.values.theta = m.rounded.energy;
  for (int i = 0; i < 12; ++i) e.values.grad[i] = m.rounded.gradient[static_cast<std::size_t>(i)];
  for (Eigen::Index col = 0; col < m.rounded.hessian.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m.rounded.hessian, col); it; ++it) {
      e.values.hess[static_cast<std::size_t>(12 * it.row() + it.col())] = it.value();
      e.values.hess[static_cast<std::size_t>(12 * it.col() + it.row())] = it.value();
    }
  e.values.uncertified = m.uncertified;
  if (!conditioning) return e;
  e.conditioning = oracle::energy_conditioning(c.x, c.rest, parameters, options.gauss_newton, e.values.theta,
                                               e.values.grad, e.values.hess);
  if (e.values.theta == 0) {
    const oracle::CertifiedTheta tx = oracle::certified_theta_derivatives(c.x);
    const oracle::CertifiedTheta tr = oracle::certified_theta_derivatives(c.rest);
    const double L = e.conditioning.length;
    const double s = L * (oracle::scaled_norm(tx.grad.data(), 12) + oracle::scaled_norm(tr.grad.data(), 12));
    const double u = unit_roundoff(Dtype::float64);
    const double bound = psi_second_at_rest(c.rest, problem, tr.theta) * (16 * u * s) * (16 * u * s) / 2;
    const Policy policy;
    e.conditioning.scale[0] = bound / ((policy.base + policy.c * 1) * u);  // error <= tolerance iff |psi| <= bound
    e.conditioning.kappa[0] = 1;
  }
  return e;
}

}  // namespace hinge::conformance
