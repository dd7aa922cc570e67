// The effects' constructors (one file each), called by make_effects (effects.cpp).
#pragma once

#include <Eigen/Eigenvalues>
#include <memory>

#include "hinge/sim/effect.hpp"

namespace hinge::sim::detail {

std::unique_ptr<Effect> make_gravity(const Context& context, const Gravity& gravity);
std::unique_ptr<Effect> make_stretching(const Context& context);
std::unique_ptr<Effect> make_bending(const Context& context, const Bending& bending, const Damping* damping);
std::unique_ptr<Effect> make_damping(const Context& context, const Damping& damping);
std::unique_ptr<Effect> make_pins(const Pins& pins);
std::unique_ptr<Effect> make_sphere(const Context& context, const Sphere& sphere);
std::unique_ptr<Effect> make_load(const Load& load);

// The slots of every coordinate's diagonal entry (3n), for the effects whose Hessian is diagonal.
std::vector<Slot> diagonal_slots(const Sparsity& sparsity);

// The "projected" treatment of a symmetric element matrix: its negative eigenvalues set to zero (the
// nearest positive semidefinite matrix in the Frobenius norm).
template <int M>
void project_to_psd(Eigen::Matrix<double, M, M>& a) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, M, M>> eig(a);
  const auto& lambda = eig.eigenvalues();
  if (lambda.minCoeff() >= 0) return;
  a = eig.eigenvectors() * lambda.cwiseMax(0.0).asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace hinge::sim::detail
