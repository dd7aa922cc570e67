// hinge/reference/assemble_impl.hpp: definitions of the templates declared in assemble.hpp, for the
// explicit-instantiation units (src/instantiate_*.cpp).
#pragma once

#include <string>

#include "hinge/core/hinge_checks.hpp"
#include "hinge/reference/assemble.hpp"
#include "hinge/reference/evaluate_impl.hpp"

namespace hinge::reference {

template <HingeScalar Scalar>
std::vector<HingeCoefficients<Scalar>> rest_state(const Mesh& rest, const Topology& topology,
                                                  const EnergyParameters& parameters) {
  check_same_mesh(rest, topology, "rest");
  std::vector<HingeCoefficients<Scalar>> coefficients;
  coefficients.reserve(topology.hinges.size());
  for (Index i = 0; i < static_cast<Index>(topology.hinges.size()); ++i) {
    coefficients.push_back(for_hinge(topology, i, [&] {  // Algorithm 1, lines 2-4
      const PreparedHinge<Scalar> p = prepare_hinge<Scalar>(hinge_coordinates(rest, topology.hinges[i]));
      HingeCoefficients<Scalar> c = rest_coefficients(parameters.model, p.stencil, bend_angle(p.stencil, p.sign),
                                                      from_double<Scalar>(parameters.k));
      c.k_d_over_dt = from_double<Scalar>(parameters.k_d_over_dt);
      return c;
    }));
  }
  return coefficients;
}

template <HingeScalar Scalar>
void set_previous_state(std::vector<HingeCoefficients<Scalar>>& coefficients, const Mesh& previous,
                        const Topology& topology) {
  check_same_mesh(previous, topology, "previous");
  for (Index i = 0; i < static_cast<Index>(topology.hinges.size()); ++i) {
    for_hinge(topology, i, [&] {
      const PreparedHinge<Scalar> p = prepare_hinge<Scalar>(hinge_coordinates(previous, topology.hinges[i]));
      const BendAngle<Scalar> b = bend_angle(p.stencil, p.sign);
      if (b.on_branch_cut) throw_folded_previous();
      coefficients[i].phi_hat = 2 * b.tan_half_theta;
    });
  }
}

// The hinge-by-hinge assembly with any per-hinge evaluation: theta_of(x, with_hessian) returns a
// ThetaDerivatives<Scalar> of the hinge x (bend angle with tan(theta/2), gradient, Hessian). assemble()
// below passes the reference's; hinge::methods passes the other methods' (autodiff, symbolic).
template <class Scalar, class ThetaOf>
MeshDerivatives<Scalar> assemble_with(const Mesh& deformed, const Topology& topology,
                                      const std::vector<HingeCoefficients<Scalar>>& coefficients, Model model,
                                      unsigned request, ThetaOf&& theta_of) {
  check_same_mesh(deformed, topology, "deformed");
  if (coefficients.size() != topology.hinges.size())
    throw std::invalid_argument("assemble: one HingeCoefficients per hinge expected");
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(topology.vertex_count);
  const bool want_grad = request & want_gradient, want_hess = request & want_hessian;
  MeshDerivatives<Scalar> out;
  if (want_grad) out.gradient = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>::Zero(n);
  std::vector<Eigen::Triplet<Scalar>> triplets;
  if (want_hess) triplets.reserve(topology.hinges.size() * (4 * 6 + 6 * 9));

  for (Index i = 0; i < static_cast<Index>(topology.hinges.size()); ++i) {
    const Hinge& hinge = topology.hinges[i];
    for_hinge(topology, i, [&] {
      const ThetaDerivatives<Scalar> d = theta_of(hinge_coordinates(deformed, hinge), want_hess);
      const Psi<Scalar> p = psi(model, coefficients[i], d.angle);
      out.energy += p.value;  // eq. (1)
      if (want_grad) {
        const Vec12<Scalar> g = energy_gradient(p, d.grad);  // eq. (2)
        for (int a = 0; a < 4; ++a) out.gradient.template segment<3>(3 * hinge.x[a]) += g.template segment<3>(3 * a);
      }
      if (!want_hess) return;
      const Mat12<Scalar> H = energy_hessian(p, d.grad, d.hess);  // eq. (3)
      for (int a = 0; a < 4; ++a)
        for (int b = a; b < 4; ++b) {  // the 10 upper blocks
          const Index va = hinge.x[a], vb = hinge.x[b];
          Mat3<Scalar> B = H.template block<3, 3>(3 * a, 3 * b);
          if (a != b && va == vb) B += B.transpose().eval();  // two local vertices, one global vertex
          const bool flip = va > vb;
          const Index row = flip ? vb : va, col = flip ? va : vb;
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
              if (row == col && r > c) continue;  // upper triangle only
              triplets.emplace_back(3 * row + r, 3 * col + c, flip ? B(c, r) : B(r, c));
            }
        }
    });
  }
  if (want_hess) {
    out.hessian.resize(n, n);
    out.hessian.setFromTriplets(triplets.begin(), triplets.end());
  }
  return out;
}

template <HingeScalar Scalar>
MeshDerivatives<Scalar> assemble(const Mesh& deformed, const Topology& topology,
                                 const std::vector<HingeCoefficients<Scalar>>& coefficients, Model model,
                                 unsigned request) {
  return assemble_with<Scalar>(
      deformed, topology, coefficients, model, request,
      [](const std::array<double, 12>& x, bool with_hessian) { return theta_derivatives<Scalar>(x, with_hessian); });
}

}  // namespace hinge::reference

// Explicit instantiation of everything evaluate.hpp and assemble.hpp declare extern, for scalar S
// (used by src/instantiate_*.cpp, one translation unit per scalar family).
#define HINGE_REFERENCE_INSTANTIATE(S)                                                                             \
  template ::hinge::reference::PreparedHinge<S> hinge::reference::prepare_hinge<S>(const std::array<double, 12>&); \
  template ::hinge::reference::ThetaDerivatives<S> hinge::reference::theta_derivatives<S>(                         \
      const std::array<double, 12>&, bool);                                                                        \
  template std::vector<::hinge::HingeCoefficients<S>> hinge::reference::rest_state<S>(                             \
      const ::hinge::Mesh&, const ::hinge::Topology&, const ::hinge::EnergyParameters&);                           \
  template void hinge::reference::set_previous_state<S>(std::vector<::hinge::HingeCoefficients<S>>&,               \
                                                        const ::hinge::Mesh&, const ::hinge::Topology&);           \
  template ::hinge::MeshDerivatives<S> hinge::reference::assemble<S>(                                              \
      const ::hinge::Mesh&, const ::hinge::Topology&, const std::vector<::hinge::HingeCoefficients<S>>&,           \
      ::hinge::Model, unsigned);
