// fast/src/faithful_theta.hpp: theta in the faithful mode (hinge/fast/faithful.hpp) from the double
// kernel's double-double quantities (hinge_kernel_lanes.hpp), within a small fraction of a unit of 2^-53
// before its one rounding to double (docs/numerics.md, "The faithful mode").
#pragma once

#include <array>

namespace hinge::fast::detail {

// What the faithful double kernel leaves for theta, each as a double-double (hi, lo), computed from the
// edges scaled by 2^-exponent (LanesOutcome::exponent).
struct FaithfulTheta {
  std::array<double, 2> minus2{}, plus2{};  // |n - n~|^2 = 4 sin^2(theta/2), |n + n~|^2 = 4 cos^2(theta/2)
  std::array<double, 2> l0_squared{};       // l_0^2
  std::array<double, 2> K{}, K_lower{};     // 1 / (l_0 2A), 1 / (l_0 2A~)
};

// |theta| with the sign `sign` (+1 or -1: the exact sign of the hinge determinant), correctly rounded
// unless within about 2^-98 of a midpoint between doubles (below: where), from the hinge x (its coordinates, unscaled)
// and f (from its edges scaled by 2^-exponent). Ziv's strategy, with three paths:
//   common: theta = 2 atan2(|n - n~|, |n + n~|) in x87 long double (sqrtl, and atan2l's fpatan, within a
//     unit of 2^-64 each) from the double-double squares; relative error below 2^-61 + 2^-99 / theta
//     (|n - n~| carries an absolute error of a few units of 2^-104). Rounded when the whole interval of
//     that error rounds to one double (all but about one hinge in a hundred);
//   otherwise 2 atan2 in float128 (libquadmath, 113 bits) from the same squares (relative error 2^-99 /
//     theta, so for theta >= 2^-20 within 2^-79);
//   nearly flat (theta < 2^-40, or undecided below 2^-20): the normals' difference is theta itself, and
//     its 2^-104 absolute error is no longer small beside it: sin theta = |D| l_0^3 K K~ with the hinge
//     determinant D = -det[x2 - x1, x0 - x1, x3 - x1] computed exactly (GMP integers: every double is an
//     integer times 2^E for the lowest exponent E among the coordinates), theta =
//     atan2(sin theta, 1 - |n - n~|^2 / 2) in float128 (relative error ~2^-98 from l_0^2, K, K~).
// The bounds assume the double-double normals within a few units of 2^-104: so they are on triangles of
// moderate shape; the cross products' cancellation on a needle multiplies that error by its shape's
// condition (2^50 on the needles of the hard families, which measured correctly rounded all the same),
// and there theta is measured, not proved, to be correctly rounded.
double faithful_theta(const std::array<double, 12>& x, int sign, int exponent, const FaithfulTheta& f);

// The hinge determinant D = -det[x2 - x1, x0 - x1, x3 - x1] of x (whose sign is theta's), times
// 2^-3 exponent, as (hi + mid + lo) 2^e with the sum in [1/2, 1) (0 when D is), each part the double
// nearest to what the previous ones leave: computed exactly (GMP integers: every double is an integer
// times 2^E for the lowest exponent E among the coordinates), rounded once to 160 bits, which holds the
// 113 of float128 and bin128. With the triangles' doubled areas |N|, |N~| and l_0:
// sin theta = D l_0 / (|N| |N~|), on nearly flat hinges the one accurate source of theta (the generic
// kernel, generic_kernel.hpp, and the faithful mode use it there).
struct ScaledDeterminant {
  double hi = 0, mid = 0, lo = 0;
  long e = 0;
};
ScaledDeterminant exact_hinge_determinant(const std::array<double, 12>& x, int exponent);

}  // namespace hinge::fast::detail
