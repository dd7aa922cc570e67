// oracle/src/hinge_energy.hpp (private to hinge::oracle): one hinge's bending term enclosed at the current
// working precision, from the exact forms of the deformed and the rest hinge: psi (eq. (1)'s term), its
// gradient psi' grad theta (eq. (2)) and Hessian psi' Hess theta + psi'' grad theta grad theta^T (eq. (3);
// the Gauss-Newton Hessian: the second term only). The certified mesh (mesh.cpp) sums these; the energies'
// condition numbers (conditioning.cpp) differentiate them.
#pragma once

#include <array>

#include "hinge/core/energy.hpp"
#include "hinge/oracle/exact.hpp"
#include "interval.hpp"

namespace hinge::oracle::detail {

struct HingeEnergy {
  Interval value;                  // psi
  std::array<Interval, 12> grad;   // psi' grad theta (exact zeros where either factor is one)
  std::array<Interval, 144> hess;  // row-major
};

// `equal`: theta == theta_bar, decided exactly (same_angle). The energy's stiffness k and viscous
// coefficient kd (viscoelastic, with phi_hat = phi_bar). Throws DomainError where psi is infinite (tan at
// +-pi), as the energies do. `deformed` needs its Hessian (exact_hinge(x, true)) when `with_hessian`.
// `weight`: the hinge's weight w in place of Algorithm 1's a (nullptr: a, from the rest hinge).
HingeEnergy hinge_energy(Model model, const Interval& k, const Interval& kd, const ExactHinge& deformed,
                         const ExactHinge& rest, bool equal, bool with_gradient, bool with_hessian, bool gauss_newton,
                         const Interval* weight = nullptr);

}  // namespace hinge::oracle::detail
