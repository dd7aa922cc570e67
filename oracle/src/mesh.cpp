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
#include "hinge_energy.hpp"
#include "hinge_intervals.hpp"
#include "interval.hpp"
#include "mesh_fast_path.hpp"
#include "mesh_scatter.hpp"

namespace hinge::oracle {
namespace {

using detail::Interval;
using detail::Rounding;
using detail::Verdict;

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
  const bool weighted = !options.weights.empty();
  if (weighted && options.weights.size() != topology.hinges.size())
    throw std::invalid_argument("certified_mesh: Options::weights needs one weight per hinge");
  if (options.fast_path && !weighted)
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
        const Interval weight(weighted ? options.weights[static_cast<std::size_t>(i)] : 0.0);
        const detail::HingeEnergy h =
            detail::hinge_energy(model, k, kd, exact[i], rest_exact[i], equal[i] != 0, want_grad || want_hess,
                                 want_hess, options.gauss_newton, weighted ? &weight : nullptr);
        energy += h.value;  // eq. (1)
        if (want_grad) {
          double squares = 0;
          for (int c = 0; c < 12; ++c) squares += square(midpoint(h.grad[c]));
          out.gradient_contributions += std::sqrt(squares);
          for (int a4 = 0; a4 < 4; ++a4)
            for (int c = 0; c < 3; ++c) {
              if (h.grad[3 * a4 + c].is_exact_zero()) continue;
              gradient[static_cast<std::size_t>(3 * hinge.x[a4] + c)] += h.grad[3 * a4 + c];  // eq. (2)
            }
        }
        if (!want_hess) return;
        double squares = 0;
        for (const Interval& v : h.hess) squares += square(midpoint(v));
        out.hessian_contributions += std::sqrt(squares);
        detail::scatter_hessian(
            hinge, [&h](int row, int col) { return h.hess[12 * row + col]; }, hessian);
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
