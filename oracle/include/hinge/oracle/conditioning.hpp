// hinge/oracle/conditioning.hpp: the condition numbers of docs/contract.md ("Condition numbers"): those
// of the conformance tolerance policy and of `hinge eval --cond`, computed from certified and exact values,
// so that they come out the same bits on every platform (they are part of the committed vectors).
#pragma once

#include <array>
#include <cstddef>

#include "hinge/core/energy.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::oracle {

// Conditioning of one case (docs/conformance.md, "Tolerance policy"). With L the longest of the five
// edge vectors and J_f the Jacobian of output group f with respect to the 12 coordinates
// (J_theta = grad theta, J_grad = Hess theta, J_hess the third derivatives, by central differences on
// the exact form with step 2^-100 L):
//   scale_f = L ||J_f||_F        kappa_f = scale_f / ||f||_2   (kappa_f = 1 where f is exactly zero)
struct Conditioning {
  double length = 0;
  std::array<double, 3> scale{};
  std::array<double, 3> kappa{};
};

// Certified outputs of `x` (stages 1 and 2: the same doubles as the fast path gives; with options.binary32
// the floats) and their conditioning. The condition numbers are those of the exact outputs, computed from
// the outputs certified in binary64 whatever the format of `values`. Throws as certified_theta_derivatives
// does.
struct ConditionedTheta {
  CertifiedTheta values;
  Conditioning conditioning;
};
ConditionedTheta certified_with_conditioning(const std::array<double, 12>& x, const Options& options = {});

// The conditioning of a hinge's bending term psi(X; R) (docs/conformance.md, "Bending energies"): L the
// longest of the ten edge vectors of X and R; J_f the Jacobian of output group f (psi; its gradient and its
// Hessian, exact or Gauss-Newton, with respect to X) with respect to the 24 coordinates of X and R, by
// central differences of enclosures at 320 bits with a step of at most 2^-100 L in every coordinate;
// scale_f = L ||J_f||_F. `values` (psi, grad 12, hess 144, as certified) give kappa_f = scale_f / ||f||_2
// (1 where f is exactly zero). Throws as certified_mesh does (DomainError where psi is infinite).
Conditioning energy_conditioning(const std::array<double, 12>& x, const std::array<double, 12>& rest,
                                 const EnergyParameters& parameters, bool gauss_newton, double energy,
                                 const std::array<double, 12>& grad, const std::array<double, 144>& hess);

// The same for the isometric bending term of quadratic.hpp (stiffness k; its Hessian is constant in X).
Conditioning quadratic_conditioning(const std::array<double, 12>& x, const std::array<double, 12>& rest, double k,
                                    double energy, const std::array<double, 12>& grad,
                                    const std::array<double, 144>& hess);

// ||v||_2 without overflow or underflow: scaled by the largest magnitude, in a fixed order of operations;
// NaN when an entry is.
double scaled_norm(const double* v, std::size_t n);

}  // namespace hinge::oracle
