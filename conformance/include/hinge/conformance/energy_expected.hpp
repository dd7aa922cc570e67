// hinge/conformance/energy_expected.hpp: what a bending term must give on an energy case (docs/conformance.md,
// "Bending energies"): the certified psi = c f(theta, theta_bar), its gradient and its Hessian (exact or
// Gauss-Newton) with respect to the deformed hinge X, and their conditioning over the 24 coordinates of X
// and the rest hinge R, as an Expected the grading takes (its theta slot holds psi).
#pragma once

#include <optional>
#include <string>

#include "hinge/conformance/energy_inputs.hpp"
#include "hinge/conformance/grading.hpp"
#include "hinge/core/energy.hpp"

namespace hinge::conformance {

// The Hessian a candidate declares: the exact one, the Gauss-Newton one c f'' grad theta grad theta^T (not
// clamped), or the projected one (the exact Hessian with its negative eigenvalues set to zero; its reference is
// a 256-bit evaluation, oracle/projected.hpp, not certified).
enum class HessianKind { exact, gauss_newton, projected };
const char* hessian_kind_name(HessianKind h);  // "exact", "gauss-newton", "projected"

struct EnergyProblem {
  Model model = Model::tan;  // shells, tan, willmore, bridson (the contract's weight: a = 3 |e_bar|^2 / A_bar)
  double k = 1;
  HessianKind hessian = HessianKind::exact;
  // The isometric bending term of oracle/quadratic.hpp instead (model unused; no weight, exact Hessian only).
  bool quadratic = false;
};
// "shells", ..., or "quadratic".
std::string energy_name(const EnergyProblem& problem);

// The certified psi (in values.theta), gradient and Hessian of `c` (oracle::certified_mesh on the hinge's two
// triangles, each output the double nearest the exact value), and, with `conditioning`, their condition
// numbers (oracle::energy_conditioning). Where psi is exactly zero, the energy group's scale is set so that
// the policy's tolerance (base + c kappa, kappa = 1 there) allows exactly the contract's bound
// |psi_candidate| <= c f''(theta_bar) (16 u (s_X + s_R))^2 / 2, s_X and s_R the theta scales L ||grad theta||
// of X and R, with the default policy. HessianKind::projected: the Hessian is oracle::projected_hessian_256's
// (scaled by w / a for another weight), its condition number kappa_H ||H|| / ||H_+|| (for quadratic, whose psi is not a
// function of theta, with the shells energy's psi'' = 2 k a: both are k a theta^2 to leading order on isometric bends).
// `weight`: the hinge's weight w in place of the contract's a = 3 |e_bar|^2 / A_bar (taken exactly; the oracle's
// interval path). Throws hinge::DomainError where psi is infinite (tan at +-pi).
Expected energy_expected(const EnergyCase& c, const EnergyProblem& problem, bool conditioning = true,
                         std::optional<double> weight = std::nullopt);

// The projected Hessian's condition number kappa_H ||H|| / ||H_+||: scale[2] (kappa_H ||H||, the exact Hessian's)
// over ||H_+|| (e's Hessian), 1 where H_+ = 0.
void set_projected_kappa(Expected& e);

// Where e's psi is exactly zero: its energy scale set (and kappa 1) so that the default policy allows exactly
// the contract's bound above (energy_expected does this; for conditioning taken from elsewhere).
// u is the dtype's unit roundoff.
void apply_zero_energy_bound(Expected& e, const EnergyCase& c, const EnergyProblem& problem,
                             std::optional<double> weight = std::nullopt, Dtype dtype = Dtype::float64);

}  // namespace hinge::conformance
