// hinge/reference/hinge_energy.hpp: one hinge's bending energy on its stencil: Algorithm 1 (the rest
// constants a, theta_bar, phi_bar of a hinge) and the chain rule of eqs. (2)-(3) that turns psi', psi''
// and theta's derivatives into the energy's gradient and Hessian.
#pragma once

#include <string>

#include "hinge/core/energy.hpp"
#include "hinge/reference/bend_angle.hpp"
#include "hinge/reference/hessian.hpp"

namespace hinge::reference {

// Algorithm 1 for one hinge: a from the rest stencil, theta_bar and phi_bar from its bend angle.
// Throws DomainError if `model` is infinite at pi and the rest hinge is folded (eq. (10)).
template <class Scalar>
HingeCoefficients<Scalar> rest_coefficients(Model model, const Stencil<Scalar>& rest,
                                            const BendAngle<Scalar>& rest_angle, const Scalar& k) {
  if (infinite_at_pi(model) && rest_angle.on_branch_cut) throw_folded_rest(model);
  HingeCoefficients<Scalar> c;
  c.k = k;
  const Scalar l0 = rest.upper.l[0];
  c.a = 6 * l0 * l0 / (rest.upper.double_area + rest.lower.double_area);  // 3 |e|^2 / A_bar, A = 2A / 2
  c.theta_bar = rest_angle.theta;
  c.phi_bar = 2 * rest_angle.tan_half_theta;  // Algorithm 1, line 2 (eq. (12))
  c.phi_hat = c.phi_bar;
  return c;
}

// Eqs. (2)-(3): grad psi = psi' grad theta; Hess psi = psi' Hess theta + psi'' grad theta grad theta^T.
template <class Scalar>
Vec12<Scalar> energy_gradient(const Psi<Scalar>& p, const Vec12<Scalar>& grad_theta) {
  return p.d1 * grad_theta;  // eq. (2)
}
template <class Scalar>
Mat12<Scalar> energy_hessian(const Psi<Scalar>& p, const Vec12<Scalar>& grad_theta, const Mat12<Scalar>& hess_theta) {
  return p.d1 * hess_theta + p.d2 * grad_theta * grad_theta.transpose();  // eq. (3)
}

}  // namespace hinge::reference
