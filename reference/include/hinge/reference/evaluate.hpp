// hinge/reference/evaluate.hpp: one hinge from its 12 input doubles (x0.x, x0.y, ..., x3.z): the exact
// validity checks of docs/contract.md, then theta, grad theta (eq. (4)) and Hess theta (eqs. (5)-(6)) in Scalar.
//
// Inputs are exact doubles. Before any arithmetic:
// - a non-finite coordinate, a zero-length hinge edge (x1 == x2) or a triangle of exactly zero area
//   (hinge::zero_area_exact) is an InputError naming which;
// - the sign of theta's numerator is decided exactly (hinge::hinge_orientation_exact), so that a hinge
//   folded flat onto itself gets theta = +pi, and near-folded hinges never jump to the wrong branch.
// Then the five edge vectors are formed by subtraction (stencil.hpp) and, for the built-in types,
// scaled by a power of two 2^-p so that the largest component is near 1: theta is scale-invariant,
// grad theta scales as 2^-p and Hess theta as 2^-2p (proofs/invariance.md), so the results are scaled
// back exactly, and no intermediate product (|N| ~ length^2, |N x Nt| ~ length^4) overflows or
// underflows for any finite input. Results are finite or the caller's conversion reports them.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "hinge/reference/bend_angle.hpp"
#include "hinge/reference/hessian.hpp"

namespace hinge::reference {

template <class Scalar>
struct PreparedHinge {
  Stencil<Scalar> stencil;  // of the scaled edges
  ExactSign sign;           // exact sign of theta's numerator
  int exponent = 0;         // true lengths = stencil lengths * 2^exponent
};

// Validates `x` exactly and builds its stencil. Throws hinge::InputError.
template <HingeScalar Scalar>
PreparedHinge<Scalar> prepare_hinge(const std::array<double, 12>& x);

template <class Scalar>
struct ThetaDerivatives {
  BendAngle<Scalar> angle;
  Vec12<Scalar> grad;  // eq. (4)
  Mat12<Scalar> hess;  // eqs. (5)-(6); left zero unless requested
};

// theta, grad theta and (if `with_hessian`) Hess theta of the hinge `x`. Throws hinge::InputError.
template <HingeScalar Scalar>
ThetaDerivatives<Scalar> theta_derivatives(const std::array<double, 12>& x, bool with_hessian = true);

// The same from a prepared hinge (no checks).
template <class Scalar>
ThetaDerivatives<Scalar> theta_derivatives(const PreparedHinge<Scalar>& p, bool with_hessian) {
  ThetaDerivatives<Scalar> d;
  d.angle = bend_angle(p.stencil, p.sign);
  d.grad = gradient(p.stencil);
  if (with_hessian) d.hess = hessian(p.stencil);
  else d.hess.setZero();
  if (p.exponent != 0) {  // undo the power-of-two scaling exactly (built-in types only)
    using std::ldexp;
    for (auto& g : d.grad) g = ldexp(g, -p.exponent);
    if (with_hessian)
      for (auto& h : d.hess.reshaped()) h = ldexp(h, -2 * p.exponent);
  }
  return d;
}

#define HINGE_REFERENCE_EVALUATE_EXTERN(S)                                          \
  extern template PreparedHinge<S> prepare_hinge<S>(const std::array<double, 12>&); \
  extern template ThetaDerivatives<S> theta_derivatives<S>(const std::array<double, 12>&, bool);
HINGE_FOR_EACH_SCALAR(HINGE_REFERENCE_EVALUATE_EXTERN)
#undef HINGE_REFERENCE_EVALUATE_EXTERN

}  // namespace hinge::reference

namespace hinge::reference {

// docs/contract.md, "well-shaped": in each triangle the smallest altitude is at least 0.15 times the
// longest edge, and 0.05 <= |theta| <= pi - 0.05 (evaluated in double; borderline cases may go either way).
bool well_shaped(const std::array<double, 12>& x);

// `count` well-shaped hinges: 12 random coordinates in a box of side 10^U(-3, 3), all offset by
// U(-offset, offset), kept when well_shaped accepts them (std::mt19937_64 seeded with `seed`: the same
// hinges on every platform with the same standard library). What `hinge demo`, the study, the benchmark
// and the tests sample.
std::vector<std::array<double, 12>> well_shaped_hinges(int count, unsigned seed, double offset = 100);

}  // namespace hinge::reference
