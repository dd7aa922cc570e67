// hinge/reference/bend_angle.hpp: the signed bend angle theta (docs/contract.md; proofs/sign-convention.md).
//
// Two forms, each used where it serves:
// - theta itself: the atan2 form of docs/contract.md, theta = atan2(((N x Nt) . e0) / |e0|, N . Nt), in
//   (-pi, pi]. atan2 of the two unnormalized products is accurate over the whole range (no acos near 0
//   or pi, where acos loses half the digits), and it needs no normalization.
// - tan(theta/2), eq. (12): tan(theta/2) = sgn(det[n, n~, e0]) |n - n~| / |n + n~|. The tan-based energies
//   need phi = 2 tan(theta/2) (eq. (8)) and its derivatives, which are polynomials in tan(theta/2); eq. (12)
//   gives it without a trigonometric call (Algorithm 1, line 2; Algorithm 2, line 4).
// Sign: theta has the sign of (n x n~) . e0: lifting x0 along +n makes theta negative.
#pragma once

#include <limits>

#include "hinge/core/energy.hpp"  // BendAngle
#include "hinge/core/errors.hpp"
#include "hinge/reference/stencil.hpp"

namespace hinge::reference {

// The sign of (N x Nt) . e0 when it is known exactly (from hinge::hinge_orientation_exact on the input
// doubles), or `computed` to take the sign of the value computed in Scalar.
enum class ExactSign { negative = -1, zero = 0, positive = 1, computed = 2 };

// atan2 form (docs/contract.md). On the branch cut (numerator exactly zero, denominator negative) the
// result is +pi, never -pi: a zero numerator is taken as +0.
// e0 is normalized before the product (the same number): |N||Nt| l0 would underflow in float on a hinge
// edge below about 2^-37 of the others, where |N||Nt| does not. Where the exact sign says theta is
// neither 0 nor pi but the computed numerator is 0 (rounding, on a nearly flat or folded hinge), the
// numerator takes the smallest value of that sign: theta is then the value of this type nearest 0 or
// +-pi, on the correct side, never a false branch cut. Both products 0 (|N||Nt| below the type's range)
// is a DomainError.
template <class Scalar>
BendAngle<Scalar> bend_angle(const Stencil<Scalar>& s, ExactSign sign = ExactSign::computed) {
  const Vec3<Scalar>& e0 = s.upper.e[0];
  Scalar y = s.N.cross(s.Nt).dot(e0 / s.upper.l[0]);  // |N||Nt| sin(theta)
  Scalar x = s.N.dot(s.Nt);                           // |N||Nt| cos(theta)
  if (y == 0 && (sign == ExactSign::negative || sign == ExactSign::positive)) {
    if (x == 0)
      throw DomainError(
          "|N||Nt| underflows in this scalar type: the triangles' areas are too small relative to the "
          "longest edge squared for its exponent range");
    using std::numeric_limits;
    y = numeric_limits<Scalar>::denorm_min() > 0 ? Scalar(numeric_limits<Scalar>::denorm_min())
                                                 : Scalar(numeric_limits<Scalar>::min());
  }
  if (sign != ExactSign::computed) {
    // Rounding may give y the wrong sign, or make an exact zero nonzero: the exact sign decides.
    if (sign == ExactSign::zero) y = Scalar(0);
    else if ((y < 0) != (sign == ExactSign::negative)) y = -y;
  }
  if (y == 0) y = Scalar(0);  // +0: atan2(-0, x < 0) would be -pi
  BendAngle<Scalar> b;
  b.theta = atan2(y, x);
  b.on_branch_cut = (y == 0 && x < 0);
  // eq. (12), with the same sign as theta
  const Vec3<Scalar>& n = s.upper.n;
  const Vec3<Scalar>& nt = s.lower.n;
  Scalar t = (n - nt).norm() / (n + nt).norm();
  b.tan_half_theta = (y < 0) ? Scalar(-t) : t;
  return b;
}

}  // namespace hinge::reference
