// hinge/core/energy.hpp: the bending energies as functions of the bend angle alone: psi(theta) with
// psi' and psi'' per model (section 2, eq. (8) and section 5), their per-hinge constants (Algorithm 1's
// output, eq. (11)), and the messages of the energies' own errors. No geometry: every evaluator (the
// reference, hinge::fast, the oracle) computes the angle its own way and hands it here. Every model and
// parameter is documented in docs/quantities.md; one hinge's energy gradient and Hessian (eqs. (2)-(3))
// are in hinge_energy.hpp.
//
//   shells        psi = k a (theta - theta_bar)^2                                  Discrete Shells
//   tan           psi = k a (phi(theta) - phi(theta_bar))^2,  phi = 2 tan(theta/2)  eq. (8)
//   willmore      psi = k a sin^2(theta/2)                                         discrete Willmore
//   bridson       psi = A (cos(theta/2) - B theta),  A = -2 k a,  B = -sin(theta_bar/2) / 2
//                 (the paper's conservative form of Bridson et al.'s force: psi' = k a (sin(theta/2)
//                 - sin(theta_bar/2)); psi(theta_bar) is not zero, forces do not care)
//   viscoelastic  psi = k a (phi - phi(theta_bar))^2 + (k_d / dt) a (phi - phi(theta_hat))^2 (section 5)
//
// a = 3 |e_bar|^2 / A_bar (A_bar: the rest areas of the two triangles, summed); k given, or from
// eq. (11). phi and its derivatives are polynomials in t = tan(theta/2) (eq. (12)):
// phi = 2t, phi' = 1 + t^2, phi'' = t (1 + t^2).
#pragma once

#include <string>
#include <string_view>

#include "hinge/core/errors.hpp"
#include "hinge/core/scalar.hpp"

namespace hinge {

enum class Model { shells, tan, willmore, bridson, viscoelastic };

std::string_view model_name(Model model);
// "shells", "tan", "willmore", "bridson", "viscoelastic"; throws std::invalid_argument otherwise.
Model parse_model(std::string_view name);
// Whether psi is infinite at theta = +-pi (then the branch cut is an error for that hinge).
constexpr bool infinite_at_pi(Model model) { return model == Model::tan || model == Model::viscoelastic; }

// The energy's parameters for a whole mesh (Algorithm 1's inputs besides the rest shape).
struct EnergyParameters {
  Model model = Model::tan;
  double k = 1;            // bending stiffness (or bending_stiffness(Y, nu, h), eq. (11))
  double k_d_over_dt = 0;  // viscoelastic only: k_d / dt
};

// The bend angle as the energies take it (computed by bend_angle.hpp in the reference, by the fast kernels
// and by the oracle each its own way).
template <class Scalar>
struct BendAngle {
  Scalar theta;           // in (-pi, pi]
  Scalar tan_half_theta;  // eq. (12); infinite on the branch cut theta = pi
  bool on_branch_cut;     // the hinge is folded flat onto itself: theta = +pi exactly
};

// The energies' errors, with their messages (hinge::DomainError):
//   "the tan energy is infinite at theta = +-pi (hinge folded flat onto itself)"
//   "rest hinge is folded flat (theta_bar = pi): the tan energy needs theta_bar in (-pi, pi) (eq. (10))"
//   "the previous state is folded flat (theta_hat = pi)"
[[noreturn]] void throw_infinite_energy(Model model);
[[noreturn]] void throw_folded_rest(Model model);
[[noreturn]] void throw_folded_previous();

// The per-hinge constants of Algorithm 1.
template <class Scalar>
struct HingeCoefficients {
  Scalar k = 0;            // bending stiffness (given, or eq. (11))
  Scalar a = 0;            // 3 |e_bar|^2 / A_bar
  Scalar theta_bar = 0;    // rest angle
  Scalar phi_bar = 0;      // phi(theta_bar) = 2 tan(theta_bar / 2), eq. (12) on the rest hinge
  Scalar k_d_over_dt = 0;  // viscoelastic: damping coefficient over the time step
  Scalar phi_hat = 0;      // viscoelastic: phi(theta_hat), theta_hat the angle at the previous step
};

// eq. (11): k = D / 2 = Y h^3 / (24 (1 - nu^2)); Y Young's modulus, nu Poisson's ratio, h thickness.
template <class Scalar>
Scalar bending_stiffness(const Scalar& Y, const Scalar& nu, const Scalar& h) {
  return Y * h * h * h / (24 * (1 - nu * nu));
}

template <class Scalar>
struct Psi {
  Scalar value;  // psi
  Scalar d1;     // psi' = d psi / d theta
  Scalar d2;     // psi''
};

// psi, psi', psi'' at the bend angle `b`. Throws DomainError where psi is infinite (tan and viscoelastic
// at theta = +-pi).
template <class Scalar>
Psi<Scalar> psi(Model model, const HingeCoefficients<Scalar>& c, const BendAngle<Scalar>& b) {
  const Scalar& theta = b.theta;
  switch (model) {
    case Model::shells: {
      const Scalar d = theta - c.theta_bar;
      return {c.k * c.a * d * d, 2 * c.k * c.a * d, 2 * c.k * c.a};
    }
    case Model::tan:
    case Model::viscoelastic: {
      const Scalar& t = b.tan_half_theta;
      using std::isfinite;
      if (b.on_branch_cut || !isfinite(t)) throw_infinite_energy(model);
      const Scalar phi = 2 * t, dphi = 1 + t * t, d2phi = t * (1 + t * t);  // eq. (8), phi = 2 tan(theta/2)
      const Scalar elastic = phi - c.phi_bar;
      Scalar value = c.k * c.a * elastic * elastic;
      Scalar force = c.k * elastic;        // d psi / d phi / (2 a)
      Scalar stiffness = c.k;              // d^2 psi / d phi^2 / (2 a)
      if (model == Model::viscoelastic) {  // section 5: one theta, two scalar parts
        const Scalar viscous = phi - c.phi_hat;
        value += c.k_d_over_dt * c.a * viscous * viscous;
        force += c.k_d_over_dt * viscous;
        stiffness += c.k_d_over_dt;
      }
      return {value, 2 * c.a * force * dphi, 2 * c.a * (stiffness * dphi * dphi + force * d2phi)};
    }
    case Model::willmore: {
      const Scalar s = sin(theta / 2);
      return {c.k * c.a * s * s, c.k * c.a * sin(theta) / 2, c.k * c.a * cos(theta) / 2};
    }
    case Model::bridson: {
      const Scalar A = -2 * c.k * c.a, B = -sin(c.theta_bar / 2) / 2;
      return {A * (cos(theta / 2) - B * theta), A * (-sin(theta / 2) / 2 - B), -A * cos(theta / 2) / 4};
    }
  }
  throw std::invalid_argument("unknown energy model");
}

}  // namespace hinge

// The names these had in hinge::reference before they moved to hinge::core (kept for one release).
namespace hinge::reference {
using hinge::BendAngle;
using hinge::bending_stiffness;
using hinge::EnergyParameters;
using hinge::HingeCoefficients;
using hinge::infinite_at_pi;
using hinge::Model;
using hinge::model_name;
using hinge::parse_model;
using hinge::Psi;
using hinge::psi;
}  // namespace hinge::reference
