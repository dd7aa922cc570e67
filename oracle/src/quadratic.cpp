// The certified isometric bending term (hinge/oracle/quadratic.hpp).
#include "hinge/oracle/quadratic.hpp"

#include <algorithm>
#include <string>

#include "hinge/core/errors.hpp"
#include "hinge_intervals.hpp"
#include "interval.hpp"
#include "quadratic_enclosure.hpp"

namespace hinge::oracle {
namespace detail {
namespace {

Int dot(const ScaledHinge& h, int a, int b, int c, int d) {  // (x_a - x_b) . (x_c - x_d), exact
  Int sum = 0;
  for (int k = 0; k < 3; ++k) sum += (h.X[3 * a + k] - h.X[3 * b + k]) * (h.X[3 * c + k] - h.X[3 * d + k]);
  return sum;
}

// p / sqrt(nn) + q / sqrt(tt), exactly zero where it is (p and q of opposite signs and p^2 tt == q^2 nn).
Interval cotangent_sum(const Int& p, const Int& q, const ExactHinge& r, const Interval& root_nn,
                       const Interval& root_tt) {
  if (sgn(p) == -sgn(q) && p * p * r.tt == q * q * r.nn) return Interval::zero();
  return Interval(p) / root_nn + Interval(q) / root_tt;
}

}  // namespace

HingeEnergy quadratic_enclosure(const ScaledHinge& x, const ScaledHinge& rest, const ExactHinge& r, const Interval& k) {
  // The cotangents of docs/quantities.md with e0 = x2 - x1, e1 = x0 - x2, e2 = x1 - x0, et1 = x3 - x2,
  // et2 = x1 - x3 of R: cot alpha1 = -(e0 . e2) / |N|, cot alpha2 = -(e0 . e1) / |N|, cot alpha~1 =
  // -(e0 . et2) / |Nt|, cot alpha~2 = -(e0 . et1) / |Nt| (the integers' 2^-2F cancels in each).
  const Interval root_nn = sqrt(Interval(r.nn)), root_tt = sqrt(Interval(r.tt));
  const Int d1 = dot(rest, 2, 1, 0, 2), d2 = dot(rest, 2, 1, 1, 0), t1 = dot(rest, 2, 1, 3, 2),
            t2 = dot(rest, 2, 1, 1, 3);
  const std::array<Interval, 4> K{-(Interval(r.s) / root_nn), cotangent_sum(-d1, -t1, r, root_nn, root_tt),
                                  cotangent_sum(-d2, -t2, r, root_nn, root_tt), -(Interval(r.s) / root_tt)};
  // c_q = 3 k / A_bar, A_bar = (|N| + |Nt|) / 2 = (sqrt(nn) + sqrt(tt)) 2^(-2 F_R) / 2.
  const Interval c = scale2(6 * (k / (root_nn + root_tt)), 2 * rest.F);
  // s = sum_j K_j (x_j - x1) (sum K = 0), in units of 2^-F_X; exactly zero at a flat rest hinge and where every
  // x_j has the same coordinate.
  bool at_flat_rest = x.F == rest.F && x.X == rest.X && sgn(r.Y) == 0 && sgn(r.X) > 0;
  std::array<Interval, 3> s{Interval::zero(), Interval::zero(), Interval::zero()};
  for (int axis = 0; axis < 3 && !at_flat_rest; ++axis)
    for (int j = 0; j < 4; ++j) {
      const Int difference = x.X[3 * j + axis] - x.X[3 + axis];
      if (sgn(difference) != 0 && !K[j].is_exact_zero()) s[axis] += K[j] * Interval(difference);
    }
  HingeEnergy out;
  out.value = scale2(c * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]), -2 * x.F);
  for (int j = 0; j < 4; ++j)
    for (int axis = 0; axis < 3; ++axis)
      out.grad[3 * j + axis] = s[axis].is_exact_zero() || K[j].is_exact_zero()
                                   ? Interval::zero()
                                   : scale2(2 * (c * K[j] * s[axis]), -x.F);  // 2 c_q K_j s
  for (int row = 0; row < 12; ++row)
    for (int col = 0; col < 12; ++col) {
      Interval& h = out.hess[12 * row + col];
      h = Interval::zero();
      if (row % 3 == col % 3 && !K[row / 3].is_exact_zero() && !K[col / 3].is_exact_zero())
        h = 2 * (c * K[row / 3] * K[col / 3]);  // 2 c_q K_i K_j I_3
    }
  return out;
}

}  // namespace detail

CertifiedEnergy certified_quadratic(const std::array<double, 12>& x, const std::array<double, 12>& rest, double k,
                                    const Options& options) {
  const ScaledHinge sx = scale_exactly(x), sr = scale_exactly(rest);
  const ExactHinge r = exact_hinge(sr, false);  // InputError for a degenerate rest triangle
  CertifiedEnergy out;
  const unsigned cap = std::max(options.max_bits, options.start_bits);
  for (unsigned bits = std::max(53u, options.start_bits);; bits *= 2) {
    if (bits > cap) bits = cap;
    out.bits = bits;
    out.uncertified.clear();
    detail::WorkingPrecision precision(bits);
    const detail::HingeEnergy e = detail::quadratic_enclosure(sx, sr, r, detail::Interval(k));
    bool open = false;
    const bool at_cap = bits >= cap;
    const auto settle = [&](const detail::Interval& v, const std::string& name, const char* what) {
      const detail::Rounding rounded = detail::round_enclosure(v);
      if (rounded.verdict == detail::Verdict::overflow) throw_outside_double(what);
      if (rounded.verdict == detail::Verdict::rounded) return rounded.value;
      open = true;
      if (!at_cap) return 0.0;
      out.uncertified.push_back(detail::flag(name, v));
      return out.uncertified.back().nearest;
    };
    out.energy = settle(e.value, "energy", "the energy");
    for (int i = 0; i < 12; ++i) out.grad[i] = settle(e.grad[i], "grad[" + std::to_string(i) + "]", "the gradient");
    for (int i = 0; i < 144; ++i) out.hess[i] = settle(e.hess[i], "hess[" + std::to_string(i) + "]", "the Hessian");
    if (!open || at_cap) break;
  }
  return out;
}

}  // namespace hinge::oracle
