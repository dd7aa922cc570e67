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

// Whether theta of `a` equals theta of `b`, decided exactly: same signs of sin (Y) and cos (X), and
// X_a^2 nn_b tt_b == X_b^2 nn_a tt_a (equal cosines).
bool same_angle(const ExactHinge& a, const ExactHinge& b);

// Rounding an enclosure to nearest: `rounded` when both end points round to the same double (then every
// point does, rounding being monotone), `overflow` when both round to the same infinity, else `open`
// (lo and hi are the end points rounded to nearest).
enum class Verdict { rounded, overflow, open };
struct Rounding {
  Verdict verdict = Verdict::open;
  double value = 0;
  double lo = 0, hi = 0;
  bool tie = false;  // rounded from a point enclosure exactly halfway between two doubles (to even)
};
Rounding round_enclosure(const Interval& v);

// The flag of an output left open at the precision cap.
Uncertified flag(const std::string& name, const Interval& v);

}  // namespace hinge::oracle::detail
