// One hinge's bending term enclosed (hinge_energy.hpp).
#include "hinge_energy.hpp"

#include <stdexcept>

#include "hinge/core/errors.hpp"
#include "hinge_intervals.hpp"

namespace hinge::oracle::detail {
namespace {

struct PsiEnclosure {
  Interval value, d1, d2;  // psi, psi', psi''
};

// psi, psi', psi'' of hinge_energy.hpp's models, enclosed. `equal`: theta == theta_bar exactly.
PsiEnclosure psi(Model model, const Interval& k, const Interval& kd, const Interval& a, const Angle& angle,
                 const Angle& rest, bool equal) {
  const Interval& theta = angle.theta;
  switch (model) {
    case Model::shells: {  // psi = k a (theta - theta_bar)^2
      const Interval d = equal ? Interval::zero() : theta - rest.theta;
      const Interval ka = k * a;
      return {ka * d * d, 2 * ka * d, 2 * ka};
    }
    case Model::tan:
    case Model::viscoelastic: {  // eq. (8): psi = k a (phi - phi_bar)^2, phi = 2 t, t = tan(theta / 2)
      if (angle.branch_cut) throw_infinite_energy(model);
      const Interval& t = angle.tan_half;
      const Interval one(1.0);
      const Interval dphi = one + t * t, d2phi = t * dphi;
      const Interval elastic = equal ? Interval::zero() : 2 * t - 2 * rest.tan_half;
      const Interval stiffness = model == Model::viscoelastic ? k + kd : k;  // phi_hat = phi_bar
      const Interval force = stiffness * elastic;
      return {stiffness * a * elastic * elastic, 2 * a * force * dphi,
              2 * a * (stiffness * dphi * dphi + force * d2phi)};
    }
    case Model::willmore: {  // psi = k a sin^2(theta / 2)
      const Interval ka = k * a;
      if (angle.exactly_zero) return {Interval::zero(), Interval::zero(), scale2(ka, -1)};
      const Interval s = sin(scale2(theta, -1));
      return {ka * s * s, scale2(ka * sin(theta), -1), scale2(ka * cos(theta), -1)};
    }
    case Model::bridson: {  // psi = A (cos(theta/2) - B theta), A = -2 k a, B = -sin(theta_bar / 2) / 2
      const Interval A = -2 * (k * a);
      const Interval B = -scale2(sin(scale2(rest.theta, -1)), -1);
      const Interval half = scale2(theta, -1);
      const Interval d1 = equal ? Interval::zero() : A * (-scale2(sin(half), -1) - B);
      return {A * (cos(half) - B * theta), d1, -scale2(A * cos(half), -2)};
    }
  }
  throw std::invalid_argument("unknown energy model");
}

}  // namespace

HingeEnergy hinge_energy(Model model, const Interval& k, const Interval& kd, const ExactHinge& e, const ExactHinge& r,
                         bool equal, bool with_gradient, bool with_hessian, bool gauss_newton, const Interval* weight) {
  HingeEnergy out;
  const Interval rest_l0 = sqrt(Interval(r.s));
  const Angle rest_angle = angle(r, rest_l0);
  // Algorithm 1: a = 3 |e_bar|^2 / A_bar = 6 s_bar / (|N_bar| + |Nt_bar|) (true lengths: 2^-F cancels).
  const Interval a = weight ? *weight : 6 * (Interval(r.s) / (sqrt(Interval(r.nn)) + sqrt(Interval(r.tt))));
  const Interval l0 = sqrt(Interval(e.s));
  const PsiEnclosure p = psi(model, k, kd, a, angle(e, l0), rest_angle, equal);
  out.value = p.value;
  if (!with_gradient && !with_hessian) return out;
  const Interval g_scale = Interval(e.g_den) * l0;
  std::array<Interval, 12> g;
  for (int c = 0; c < 12; ++c) g[c] = sgn(e.g[c]) == 0 ? Interval::zero() : scale2(Interval(e.g[c]) / g_scale, e.F);
  for (int c = 0; c < 12; ++c)
    out.grad[c] = g[c].is_exact_zero() || p.d1.is_exact_zero() ? Interval::zero() : p.d1 * g[c];
  if (!with_hessian) return out;
  const Interval h_scale = Interval(e.h_den) * l0;
  for (int row = 0; row < 12; ++row)
    for (int col = 0; col < 12; ++col) {
      const Int& num = e.h[12 * row + col];
      Interval& v = out.hess[12 * row + col];
      v = Interval::zero();
      if (!gauss_newton && sgn(num) != 0 && !p.d1.is_exact_zero()) v = p.d1 * scale2(Interval(num) / h_scale, 2 * e.F);
      if (!g[row].is_exact_zero() && !g[col].is_exact_zero() && !p.d2.is_exact_zero()) v += p.d2 * g[row] * g[col];
    }
  return out;
}

}  // namespace hinge::oracle::detail
