// tests/properties/mesh_support.hpp: a mesh's energy, gradient and Hessian (dense, both triangles) with
// the scales its comparisons are measured against, and the comparison itself.
//
// Scales (docs/testing.md). The mesh sums are sums of hinge terms psi_i'(theta_i) grad theta_i and
// psi_i' Hess theta_i + psi_i'' grad theta_i grad theta_i^T that may cancel; an error of relative size e
// in theta_i's derivatives and an absolute error e in theta_i (which moves psi' by psi'' e) are measured
// against
//   energy:   sum_i |psi_i| + |psi_i'|
//   gradient: sum_i (|psi_i'| + |psi_i''|) |grad theta_i|
//   Hessian:  sum_i (|psi_i'| + |psi_i''|) (|Hess theta_i| + |grad theta_i|^2)
// and kappa is the largest condition number of the mesh's hinges.
#pragma once

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "hinge/reference/assemble.hpp"
#include "property_support.hpp"

// RapidCheck shows drawn values with showValue, found by argument-dependent lookup.
namespace hinge::reference {
inline void showValue(Model model, std::ostream& os) { os << "model " << model_name(model); }
}  // namespace hinge::reference

namespace hinge::test {

// The full symmetric matrix from the stored upper triangle.
template <class S>
Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> dense(const Eigen::SparseMatrix<S>& upper) {
  Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> m =
      Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>::Zero(upper.rows(), upper.cols());
  for (Eigen::Index c = 0; c < upper.outerSize(); ++c)
    for (typename Eigen::SparseMatrix<S>::InnerIterator it(upper, c); it; ++it) {
      m(it.row(), it.col()) = it.value();
      m(it.col(), it.row()) = it.value();
    }
  return m;
}

template <class S>
struct MeshEvaluation {
  Topology topology;
  S energy = 0;
  Eigen::Matrix<S, Eigen::Dynamic, 1> gradient;
  Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> hessian;
  std::vector<double> theta;  // per hinge (Topology::hinges order), from the reference in double
  double kappa = 1;           // the largest condition number of the hinges
  double energy_scale = 0, gradient_scale = 0, hessian_scale = 0;
};

// The scales and theta per hinge, from the reference in double (sizes only).
template <class S>
void measure_scales(const Mesh& deformed, const std::vector<HingeCoefficients<double>>& coefficients, Model model,
                    MeshEvaluation<S>& out) {
  out.theta.clear();
  for (std::size_t i = 0; i < out.topology.hinges.size(); ++i) {
    const Coordinates x = hinge_coordinates(deformed, out.topology.hinges[i]);
    const auto d = reference::theta_derivatives<double>(x);
    const auto p = psi(model, coefficients[i], d.angle);
    const double w = std::abs(p.d1) + std::abs(p.d2), g = d.grad.norm();
    out.energy_scale += std::abs(p.value) + std::abs(p.d1);
    out.gradient_scale += w * g;
    out.hessian_scale += w * (d.hess.norm() + g * g);
    out.theta.push_back(d.angle.theta);
    out.kappa = std::max(out.kappa, condition_number(x));
  }
}

// hinge::reference::assemble of `deformed` with the rest state of `rest` (energy `model`, stiffness k).
template <class S>
MeshEvaluation<S> evaluate_mesh(const Mesh& deformed, const Mesh& rest, Model model, double k) {
  MeshEvaluation<S> out;
  out.topology = build_topology(deformed);
  const EnergyParameters parameters{model, k, 0};
  const auto coefficients = reference::rest_state<S>(rest, out.topology, parameters);
  const auto d = reference::assemble<S>(deformed, out.topology, coefficients, model);
  out.energy = d.energy;
  out.gradient = d.gradient;
  out.hessian = dense(d.hessian);
  measure_scales(deformed, reference::rest_state<double>(rest, out.topology, parameters), model, out);
  return out;
}

// Compares a mesh evaluation `a` with another one's (energy, gradient, hessian), already brought to a's
// numbering and frame: each within `bound` units of u against max(its own size, a's scale).
template <class S, class G, class H>
void expect_same_mesh(const std::string& property, const MeshCase& mc, const MeshEvaluation<S>& a, const S& energy,
                      const G& gradient, const H& hessian, double bound, const std::string& reason) {
  const double u = u_of<S>();
  const double units = std::max({scalar_units(a.energy, energy, u, a.energy_scale),
                                 normwise_units_between(a.gradient, gradient, u, a.gradient_scale),
                                 normwise_units_between(a.hessian, hessian, u, a.hessian_scale)});
  check_units(property, units, bound, a.kappa, [&] {
    Report r(property);
    std::ostringstream m;
    showValue(mc, m);
    r.line("mesh " + m.str());
    r.line("largest hinge condition number kappa = " + show_exactly(a.kappa));
    r.value("energy", a.energy).value("energy (other)", energy);
    r.values("gradient", a.gradient.transpose()).values("gradient (other)", gradient.transpose());
    r.line("scales: energy " + show_exactly(a.energy_scale) + ", gradient " + show_exactly(a.gradient_scale) +
           ", hessian " + show_exactly(a.hessian_scale));
    return r.finish(units, bound, reason, a.hessian, hessian);
  });
}

}  // namespace hinge::test
