// oracle/src/hinge_intervals.hpp: enclosures of one hinge's theta, tan(theta/2), gradient and Hessian
// from its exact form, at the working precision (private to hinge::oracle).
#pragma once

#include <array>
#include <string>

#include "hinge/oracle/oracle.hpp"

#include "hinge/oracle/exact.hpp"
#include "interval.hpp"

namespace hinge::oracle::detail {

// num 2^shift / (den root), root an enclosure of sqrt(s): a gradient (shift F) or Hessian (shift 2F)
// entry. An exactly zero numerator gives the point interval [0, 0].
Interval quotient(const Int& num, const Int& den, const Interval& root, long shift);

// theta = atan2(Y / l0, X) and t = tan(theta / 2), by the half-angle forms that never cancel:
//   X >= 0:  t = (Y / l0) / (r + X),    X < 0:  t = l0 (r - X) / Y,    r = |N| |Nt| = sqrt(nn tt),
// theta = 2 atan(t). Exact cases: Y = 0 and X > 0 gives theta = t = 0 (point intervals); Y = 0 and
// X < 0 is the branch cut, theta = +pi (docs/contract.md) and t infinite (`branch_cut`, t left NaN).
struct Angle {
  Interval theta, tan_half;
  bool branch_cut = false;
  bool exactly_zero = false;
};
Angle angle(const ExactHinge& e, const Interval& l0);

using oracle::same_angle;  // exact.hpp

// The format outputs are rounded to (Options::binary32): binary64 with its whole range (subnormals
// included, overflow to infinity), or binary32 with a 24-bit significand, its values held in doubles,
// whose outputs must be zero or normal floats.
enum class Format { binary64, binary32 };

// The value of `x` rounded to nearest (ties to even) in the format; for binary32 with an unbounded
// exponent (so 2^128 above FLT_MAX, values below FLT_MIN kept as 24-bit numbers), as a double (exact
// within double's range).
double round_to(mpfr_srcptr x, Format format);

// Rounding an enclosure to nearest: `rounded` when both end points round to the same value of the format
// (then every point does, rounding being monotone); `overflow` when they round to the same infinity
// (binary64) or both to at least 2^128 in magnitude with one sign (binary32); `underflow` (binary32 only)
// when both round below FLT_MIN = 2^-126 in magnitude and the enclosure is not the point zero (every
// nonzero point of it is outside the normal range: the oracle encloses nonzero values only); else `open`
// (lo and hi are the end points rounded).
enum class Verdict { rounded, overflow, underflow, open };
struct Rounding {
  Verdict verdict = Verdict::open;
  double value = 0;
  double lo = 0, hi = 0;
  bool tie = false;  // rounded from a point enclosure exactly halfway between two values (to even)
};
Rounding round_enclosure(const Interval& v, Format format = Format::binary64);

// The verdict on a value already rounded to the format: `rounded`, `overflow` or `underflow`.
Verdict range_of(double rounded, Format format);

// Where rounding switches between a < b, two adjacent values of the format (rounded end points of an
// enclosure): `boundary` = their midpoint (for binary64's pair (DBL_MAX, inf), 2^1024 - 2^970, where
// rounding overflows), exact at 64 bits, and `at_boundary` the value a tie there rounds to (the even one).
// False when a and b are not adjacent (the enclosure is still too wide).
bool rounding_boundary(double a, double b, Format format, Real& boundary, double& at_boundary);

// The branch cut theta = +pi (docs/contract.md), rounded to the format.
double branch_cut_theta(Format format);

// The flag of an output left open at the precision cap (its nearest value rounded to the format).
Uncertified flag(const std::string& name, const Interval& v, Format format = Format::binary64);

}  // namespace hinge::oracle::detail
