// The certified mesh oracle (hinge/oracle/mesh.hpp).
#include "hinge/oracle/mesh.hpp"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "hinge/core/errors.hpp"
#include "hinge/core/hinge_checks.hpp"
#include "hinge_intervals.hpp"
#include "interval.hpp"
#include "mesh_fast_path.hpp"
#include "mesh_scatter.hpp"

namespace hinge::oracle {
namespace {

using detail::Interval;
using detail::Rounding;
using detail::Verdict;

struct PsiEnclosure {
  Interval value, d1, d2;  // psi, psi', psi''
};

// psi, psi', psi'' of hinge_energy.hpp's models, enclosed. `equal`: theta == theta_bar exactly.
PsiEnclosure psi(Model model, const Interval& k, const Interval& kd, const Interval& a, const detail::Angle& angle,
                 const detail::Angle& rest, bool equal) {
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

double midpoint(const Interval& v) {
  detail::Real m(mpfi_get_prec(v.get()));
  mpfi_mid(m.get(), v.get());
  return mpfr_get_d(m.get(), MPFR_RNDN);
}
double square(double v) { return v * v; }

std::string entry_name(Eigen::Index r, Eigen::Index c) {
  return "hessian(" + std::to_string(r) + "," + std::to_string(c) + ")";
}

}  // namespace

CertifiedMesh certified_mesh(const Mesh& deformed, const Mesh& rest, const Topology& topology,
                             const EnergyParameters& parameters, unsigned request, const Options& options) {
  if (options.binary32) throw std::invalid_argument("certified_mesh: Options::binary32 is for one hinge only");
  check_same_mesh(deformed, topology, "deformed");
  check_same_mesh(rest, topology, "rest");
  if (options.fast_path)
    if (std::optional<CertifiedMesh> fast =
            detail::fast_mesh(deformed, rest, topology, parameters, request, options.gauss_newton))
      return *fast;
  const bool want_grad = request & want_gradient, want_hess = request & want_hessian;
  const Model model = parameters.model;
  const auto hinge_count = static_cast<Index>(topology.hinges.size());
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(topology.vertex_count);

  // The exact stage, once: it does not depend on the working precision. Checks (and their messages)
  // follow hinge::reference::rest_state and assemble.
  std::vector<ExactHinge> rest_exact, exact;
  std::vector<char> equal;
  rest_exact.reserve(topology.hinges.size());
  exact.reserve(topology.hinges.size());
  for (Index i = 0; i < hinge_count; ++i)
    for_hinge(topology, i, [&] {
      rest_exact.push_back(exact_hinge(hinge_coordinates(rest, topology.hinges[i]), false));
      const ExactHinge& r = rest_exact.back();
      if (infinite_at_pi(model) && sgn(r.Y) == 0 && sgn(r.X) < 0) throw_folded_rest(model);
    });
  for (Index i = 0; i < hinge_count; ++i)
    for_hinge(topology, i, [&] {
      exact.push_back(exact_hinge(hinge_coordinates(deformed, topology.hinges[i]), want_hess));
      equal.push_back(detail::same_angle(exact.back(), rest_exact[i]));
    });

  CertifiedMesh out;
  const unsigned cap = std::max(options.max_bits, options.start_bits);
  for (unsigned bits = std::max(53u, options.start_bits);; bits *= 2) {
    if (bits > cap) bits = cap;
    out.bits = bits;
    out.uncertified.clear();
    out.gradient_contributions = out.hessian_contributions = 0;
    detail::WorkingPrecision precision(bits);
    const Interval k(parameters.k), kd(parameters.k_d_over_dt);
    Interval energy = Interval::zero();
    std::vector<Interval> gradient(want_grad ? static_cast<std::size_t>(n) : 0, Interval::zero());
    std::map<std::pair<Eigen::Index, Eigen::Index>, Interval> hessian;  // upper triangle (row <= col)

    for (Index i = 0; i < hinge_count; ++i) {
      const Hinge& hinge = topology.hinges[i];
      for_hinge(topology, i, [&] {
        const ExactHinge& r = rest_exact[i];
        const ExactHinge& e = exact[i];
        const Interval rest_l0 = sqrt(Interval(r.s));
        const detail::Angle rest_angle = detail::angle(r, rest_l0);
        // Algorithm 1: a = 3 |e_bar|^2 / A_bar = 6 s_bar / (|N_bar| + |Nt_bar|) (true lengths: 2^-F cancels).
        const Interval a = 6 * (Interval(r.s) / (sqrt(Interval(r.nn)) + sqrt(Interval(r.tt))));
        const Interval l0 = sqrt(Interval(e.s));
        const detail::Angle angle = detail::angle(e, l0);
        const PsiEnclosure p = psi(model, k, kd, a, angle, rest_angle, equal[i] != 0);
        energy += p.value;  // eq. (1)
        if (!want_grad && !want_hess) return;
        const Interval g_scale = Interval(e.g_den) * l0;
        std::array<Interval, 12> g;
        for (int c = 0; c < 12; ++c)
          g[c] = sgn(e.g[c]) == 0 ? Interval::zero() : scale2(Interval(e.g[c]) / g_scale, e.F);
        if (want_grad) {
          double squares = 0;
          for (int c = 0; c < 12; ++c) squares += square(midpoint(p.d1 * g[c]));
          out.gradient_contributions += std::sqrt(squares);
        }
        if (want_grad)
          for (int a4 = 0; a4 < 4; ++a4)
            for (int c = 0; c < 3; ++c) {
              if (g[3 * a4 + c].is_exact_zero() || p.d1.is_exact_zero()) continue;
              gradient[static_cast<std::size_t>(3 * hinge.x[a4] + c)] += p.d1 * g[3 * a4 + c];  // eq. (2)
            }
        if (!want_hess) return;
        const Interval h_scale = Interval(e.h_den) * l0;
        std::array<Interval, 144> H;  // eq. (3): psi' H + psi'' g g^T (Gauss-Newton: the second term), once per entry
        double squares = 0;
        for (int row = 0; row < 12; ++row)
          for (int col = 0; col < 12; ++col) {
            const Int& num = e.h[12 * row + col];
            Interval& v = H[12 * row + col];
            v = Interval::zero();
            if (!options.gauss_newton && sgn(num) != 0 && !p.d1.is_exact_zero())
              v = p.d1 * scale2(Interval(num) / h_scale, 2 * e.F);
            if (!g[row].is_exact_zero() && !g[col].is_exact_zero() && !p.d2.is_exact_zero())
              v += p.d2 * g[row] * g[col];
            squares += square(midpoint(v));
          }
        out.hessian_contributions += std::sqrt(squares);
        detail::scatter_hessian(
            hinge, [&H](int row, int col) { return H[12 * row + col]; }, hessian);
      });
    }

    // Round every output; an open one sends the whole mesh to the next precision.
    bool open = false;
    const bool at_cap = bits >= cap;
    auto settle = [&](const Interval& v, const std::string& name, const char* what) -> double {
      const Rounding r = detail::round_enclosure(v);
      if (r.verdict == Verdict::overflow) throw_outside_double(what);
      if (r.verdict == Verdict::rounded) return r.value;
      open = true;
      if (at_cap) {
        out.uncertified.push_back(detail::flag(name, v));
        return out.uncertified.back().nearest;
      }
      return 0;
    };
    out.rounded.energy = settle(energy, "energy", "the energy");
    out.rounded.gradient.assign(gradient.size(), 0.0);
    for (std::size_t c = 0; c < gradient.size(); ++c)
      out.rounded.gradient[c] = settle(gradient[c], "gradient[" + std::to_string(c) + "]", "the gradient");
    if (want_hess) {
      std::vector<Eigen::Triplet<double>> triplets;
      triplets.reserve(hessian.size());
      for (const auto& [key, v] : hessian)
        triplets.emplace_back(key.first, key.second, settle(v, entry_name(key.first, key.second), "the Hessian"));
      out.rounded.hessian.resize(n, n);
      out.rounded.hessian.setFromTriplets(triplets.begin(), triplets.end());
    }
    if (!open || at_cap) break;
  }
  return out;
}

}  // namespace hinge::oracle
