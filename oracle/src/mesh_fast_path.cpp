// The mesh oracle's fast path (mesh_fast_path.hpp). The sums, the pattern and the order are mesh.cpp's:
// only the arithmetic differs (bounded double-double instead of MPFI), and an output is kept only when
// decided, so the doubles are the same.
#include "mesh_fast_path.hpp"

#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "fast_path.hpp"
#include "hinge/core/hinge_checks.hpp"
#include "hinge/oracle/exact.hpp"
#include "hinge_intervals.hpp"
#include "mesh_scatter.hpp"

namespace hinge::oracle::detail {
namespace {

struct PsiBounded {
  Bounded value, d1, d2;  // psi, psi', psi''
};

// theta - theta_bar (shells) or t - t_bar (tan): the quantity psi' vanishes with.
Bounded elastic(Model model, const BoundedHinge& h, const BoundedHinge& rest) {
  return model == Model::shells ? h.theta - rest.theta : Bounded(2.0) * h.tan_half - Bounded(2.0) * rest.tan_half;
}

// psi, psi', psi'' of hinge_energy.hpp's models with sums and products only (mesh.cpp's psi, the same
// formulas); `equal`: theta == theta_bar exactly (then the difference is an exact zero).
PsiBounded psi(Model model, double k, double kd, const Bounded& a, const BoundedHinge& h, const BoundedHinge& rest,
               bool equal) {
  const Bounded two(2.0);
  const Bounded d = equal ? Bounded(0.0) : elastic(model, h, rest);
  if (model == Model::shells) {  // psi = k a (theta - theta_bar)^2
    const Bounded ka = Bounded(k) * a;
    return {ka * d * d, two * ka * d, two * ka};
  }
  // tan, viscoelastic: eq. (8), psi = k a (phi - phi_bar)^2, phi = 2 t, t = tan(theta / 2)
  const Bounded& t = h.tan_half;
  const Bounded dphi = Bounded(1.0) + t * t, d2phi = t * dphi;
  const Bounded stiffness = model == Model::viscoelastic ? Bounded(k) + Bounded(kd) : Bounded(k);
  const Bounded force = stiffness * d;
  return {stiffness * a * d * d, two * a * force * dphi, two * a * (stiffness * dphi * dphi + force * d2phi)};
}

// Whether theta == theta_bar, when the bounds cannot tell (every hinge of a mesh at rest): decided in
// integers (same_angle), as mesh.cpp decides it; nothing when they differ by less than the bounds see.
std::optional<bool> equal_angles(Model model, const BoundedHinge& h, const BoundedHinge& rest,
                                 const std::array<double, 12>& x, const std::array<double, 12>& x_rest) {
  const Bounded d = elastic(model, h, rest);
  if (is_exact_zero(d)) return true;
  if (bounded::lower(d) > 0) return false;
  if (same_angle(exact_hinge(x, false), exact_hinge(x_rest, false))) return true;
  return std::nullopt;
}

}  // namespace

std::optional<CertifiedMesh> fast_mesh(const Mesh& deformed, const Mesh& rest, const Topology& topology,
                                       const EnergyParameters& parameters, unsigned request, bool gauss_newton) {
  const Model model = parameters.model;
  if (model != Model::shells && model != Model::tan && model != Model::viscoelastic) return std::nullopt;
  const bool want_grad = request & want_gradient, want_hess = request & want_hessian;
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(topology.vertex_count);
  Bounded energy;
  std::vector<Bounded> gradient(want_grad ? static_cast<std::size_t>(n) : 0);
  std::map<std::pair<Eigen::Index, Eigen::Index>, Bounded> hessian;  // upper triangle (row <= col)
  CertifiedMesh out;
  for (std::size_t i = 0; i < topology.hinges.size(); ++i) {
    const Hinge& hinge = topology.hinges[i];
    const std::array<double, 12> x = hinge_coordinates(deformed, hinge), x_rest = hinge_coordinates(rest, hinge);
    const std::optional<BoundedHinge> r = bounded_hinge(x_rest, false);
    const std::optional<BoundedHinge> h = bounded_hinge(x, want_grad || want_hess);
    if (!r || !h) return std::nullopt;
    const std::optional<bool> equal = equal_angles(model, *h, *r, x, x_rest);
    if (!equal) return std::nullopt;
    const PsiBounded p = psi(model, parameters.k, parameters.k_d_over_dt, r->a, *h, *r, *equal);
    energy = energy + p.value;  // eq. (1)
    if (want_grad) {
      std::array<Bounded, 12> dg;  // psi' grad theta, the hinge's own energy gradient
      double squares = 0;
      for (int c = 0; c < 12; ++c) {
        dg[c] = p.d1 * h->grad[c];
        squares += dg[c].hi * dg[c].hi;  // the value rounded to double, as mesh.cpp's midpoints
      }
      out.gradient_contributions += std::sqrt(squares);
      for (int a4 = 0; a4 < 4; ++a4)
        for (int c = 0; c < 3; ++c) {
          Bounded& g = gradient[static_cast<std::size_t>(3 * hinge.x[a4] + c)];
          g = g + dg[3 * a4 + c];  // eq. (2)
        }
    }
    if (!want_hess) continue;
    std::array<Bounded, 144> H;  // eq. (3): psi' Hess theta + psi'' grad theta grad theta^T (Gauss-Newton: the
                                 // second term), once per entry
    double squares = 0;
    for (int row = 0; row < 12; ++row)
      for (int col = 0; col < 12; ++col) {
        Bounded& v = H[12 * row + col];
        v = p.d2 * h->grad[row] * h->grad[col];
        if (!gauss_newton) v = p.d1 * h->hess[12 * row + col] + v;
        squares += v.hi * v.hi;  // the value rounded to double, as mesh.cpp's midpoints
      }
    out.hessian_contributions += std::sqrt(squares);
    auto local = [&H](int row, int col) { return H[12 * row + col]; };
    scatter_hessian(hinge, local, hessian);
  }
  if (!decide(energy, 0, out.rounded.energy)) return std::nullopt;
  out.rounded.gradient.assign(gradient.size(), 0.0);
  for (std::size_t c = 0; c < gradient.size(); ++c)
    if (!decide(gradient[c], 0, out.rounded.gradient[c])) return std::nullopt;
  if (want_hess) {
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(hessian.size());
    for (const auto& [key, v] : hessian) {
      double value = 0;
      if (!decide(v, 0, value)) return std::nullopt;
      triplets.emplace_back(key.first, key.second, value);
    }
    out.rounded.hessian.resize(n, n);
    out.rounded.hessian.setFromTriplets(triplets.begin(), triplets.end());
  }
  return out;
}

}  // namespace hinge::oracle::detail
