// hinge/core/results.hpp: what evaluations return. A mesh evaluation (hinge::reference::assemble,
// hinge::fast::Assembler) fills MeshDerivatives in its scalar type; the commands and bindings take every
// result rounded to double (RoundedTheta for one hinge, RoundedMesh for a mesh).
//
// Layout (docs/contract.md): variables x0.x, x0.y, ..., x3.z for a hinge (gradient 12, Hessian 144
// row-major); global index 3 v + c for a mesh, whose Hessian is stored as its upper triangle (row <= col),
// 3n x 3n: use it as H.selfadjointView<Eigen::Upper>().
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

namespace hinge {

// What to compute; anything not requested is left empty (and costs nothing).
enum Request : unsigned { want_energy = 1u, want_gradient = 2u, want_hessian = 4u, want_all = 7u };

template <class Scalar>
struct MeshDerivatives {
  Scalar energy = 0;
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> gradient;  // dE/dx, 3n (empty unless requested)
  Eigen::SparseMatrix<Scalar> hessian;                // upper triangle of d2E/dx2 (empty unless requested)
};

struct RoundedTheta {
  double theta = 0;
  std::array<double, 12> grad{};
  std::array<double, 144> hess{};  // row-major
};

struct RoundedMesh {
  double energy = 0;
  std::vector<double> gradient;         // empty unless requested
  Eigen::SparseMatrix<double> hessian;  // upper triangle; empty unless requested
};

}  // namespace hinge

// The names these had in hinge::reference before they moved to hinge::core (kept for one release).
namespace hinge::reference {
using hinge::MeshDerivatives;
using hinge::Request;
using hinge::RoundedMesh;
using hinge::RoundedTheta;
using hinge::want_all;
using hinge::want_energy;
using hinge::want_gradient;
using hinge::want_hessian;
}  // namespace hinge::reference
