// tests/conformance/candidates/energy_term.hpp: a bending term as a simulator writes it, in the layout of
// hinge_energy_candidate (hinge/candidate.h): the tan energy psi = k w (phi(theta) - phi(theta_bar))^2, phi =
// 2 tan(theta / 2) (eq. (8)), k = 1, w = 3 |e_bar|^2 / A_bar the contract's weight, each hinge on its own from
// hinge::reference's per-hinge code: Algorithm 1 on the rest hinge (rest_coefficients), psi, psi', psi''
// (hinge/core/energy.hpp) and the chain rule of eqs. (2)-(3) (hinge_energy.hpp). The deliberately wrong terms
// beside it change one thing (`weight_factor`, or a crash).
#pragma once

#include <array>
#include <exception>

#include "hinge/candidate.h"
#include "hinge/reference/evaluate.hpp"
#include "hinge/reference/hinge_energy.hpp"

namespace candidates {

inline std::array<double, 12> hinge_input(const double x[12]) {
  std::array<double, 12> in;
  for (int i = 0; i < 12; ++i) in[i] = x[i];
  return in;
}

// psi, its gradient and exact Hessian at x with the rest hinge `rest`, w multiplied by `weight_factor`;
// false when the pair cannot be evaluated (a degenerate hinge, tan at +-pi).
inline bool tan_term(const double x[12], const double rest[12], double weight_factor, double* energy, double grad[12],
                     double hess[144]) {
  namespace ref = hinge::reference;
  try {
    // The rest hinge's stencil is scaled by a power of two (evaluate.hpp): a = 3 |e_bar|^2 / A_bar and theta_bar
    // do not change with it.
    const ref::PreparedHinge<double> r = ref::prepare_hinge<double>(hinge_input(rest));
    hinge::HingeCoefficients<double> c =
        ref::rest_coefficients(hinge::Model::tan, r.stencil, ref::bend_angle(r.stencil, r.sign), 1.0);
    c.a *= weight_factor;
    const ref::ThetaDerivatives<double> d = ref::theta_derivatives<double>(hinge_input(x), true);
    const hinge::Psi<double> p = hinge::psi(hinge::Model::tan, c, d.angle);
    const ref::Vec12<double> g = ref::energy_gradient(p, d.grad);
    const ref::Mat12<double> h = ref::energy_hessian(p, d.grad, d.hess);
    *energy = p.value;
    for (int i = 0; i < 12; ++i) grad[i] = g[i];
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) hess[12 * i + j] = h(i, j);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace candidates
