// The projected Hessian at 256 bits (hinge/oracle/projected.hpp): positive semidefinite, H itself where H is,
// and what a double eigendecomposition gives to within its own error.
#include "hinge/oracle/projected.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "hinge/core/mesh.hpp"
#include "hinge/oracle/mesh.hpp"

namespace {

using X12 = std::array<double, 12>;
using Mat = Eigen::Matrix<double, 12, 12>;
constexpr double u = 0x1p-53;

const X12 rest{0.25, 1.0, 0.1, 0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 1.75, -0.75, 0.2};
const X12 bent{0.3, 0.9, 0.6, 0.1, -0.05, 0.02, 1.4, 0.1, -0.1, 1.8, -0.7, 0.5};

Mat as_matrix(const std::array<double, 144>& h) {
  return Eigen::Map<const Eigen::Matrix<double, 12, 12, Eigen::RowMajor>>(h.data());
}

// The certified exact Hessian of the term (the mesh oracle on the hinge's two triangles).
Mat exact_hessian(const X12& x, const X12& r, hinge::Model model) {
  hinge::EnergyParameters p;
  p.model = model;
  const hinge::Mesh mx = hinge::hinge_mesh(x), mr = hinge::hinge_mesh(r);
  const auto m = hinge::oracle::certified_mesh(mx, mr, hinge::build_topology(mx), p);
  Mat H = Eigen::MatrixXd(m.rounded.hessian).selfadjointView<Eigen::Upper>();
  return H;
}

TEST(Projected, TheResultIsPositiveSemidefiniteAndAgreesWithADoubleEigendecomposition) {
  for (const hinge::Model model : {hinge::Model::tan, hinge::Model::shells, hinge::Model::bridson}) {
    hinge::EnergyParameters p;
    p.model = model;
    const Mat P = as_matrix(hinge::oracle::projected_hessian_256(bent, rest, p));
    EXPECT_TRUE(P.isApprox(P.transpose(), 0)) << hinge::model_name(model);
    const Eigen::SelfAdjointEigenSolver<Mat> eig(P);
    // Rounding P to doubles moves its eigenvalues by at most 12 u ||P|| (Weyl; 144 entries within u each).
    EXPECT_GE(eig.eigenvalues().minCoeff(), -12 * u * P.norm()) << hinge::model_name(model);
    const Mat H = exact_hessian(bent, rest, model);
    const Eigen::SelfAdjointEigenSolver<Mat> eh(H);
    const Mat D = eh.eigenvectors() * eh.eigenvalues().cwiseMax(0).asDiagonal() * eh.eigenvectors().transpose();
    // Eigen's backward-stable decomposition in double: within a few hundred u ||H|| (12 x 12, Jacobi-free QR).
    EXPECT_LE((P - D).norm(), 256 * u * H.norm()) << hinge::model_name(model);
  }
}

TEST(Projected, APositiveSemidefiniteHessianIsItsOwnProjection) {
  // At rest the tan and shells Hessians are psi'' grad theta grad theta^T: rank one, positive.
  hinge::EnergyParameters p;
  p.model = hinge::Model::shells;
  const Mat P = as_matrix(hinge::oracle::projected_hessian_256(rest, rest, p));
  const Mat H = exact_hessian(rest, rest, hinge::Model::shells);
  EXPECT_LE((P - H).norm(), 4 * u * H.norm());  // both within one rounding of the same exact matrix
}

TEST(Projected, WhatIsTakenAwayIsNegativeSemidefinite) {
  hinge::EnergyParameters p;
  p.model = hinge::Model::tan;
  const Mat P = as_matrix(hinge::oracle::projected_hessian_256(bent, rest, p));
  const Mat H = exact_hessian(bent, rest, hinge::Model::tan);
  const Eigen::SelfAdjointEigenSolver<Mat> eig(H - P);
  EXPECT_LE(eig.eigenvalues().maxCoeff(), 32 * u * H.norm());
  EXPECT_LT(eig.eigenvalues().minCoeff(), 0);  // this bent hinge's tan Hessian is indefinite: something is removed
}

}  // namespace
