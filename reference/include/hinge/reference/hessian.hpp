// hinge/reference/hessian.hpp: Hess theta, eqs. (5)-(6), block by block (proofs/hessian.md).
// Blocks H_ij = d^2 theta / (dx_i dx_j), rows indexing the components of x_i; variables x0..x3 (12).
//
// Errata (proofs/errata.md), applied below:
// - E1: eq. (5) prints P_ij = omega_ij cos(alpha_i) M_j^T. The cosine belongs to the OTHER hinge vertex:
//   P_1j = omega_1j cos(alpha_2) M_j^T and P_2j = omega_2j cos(alpha_1) M_j^T, as in eq. (4), where x1
//   carries cos(alpha2). Eq. (7)'s d_i agrees with the corrected form.
// - E2: eq. (5) prints Q~_j = omega_0j M~_j; it is omega~_0j M~_j (the lower triangle's own altitudes).
// - E5: the tilde edge normals m~_i point out of T~ (stencil.hpp); E6: rows of H_ij index x_i.
// Checked: proofs/checks/check_hessian.py (all 16 blocks against derivatives of theta's definition).
#pragma once

#include "hinge/reference/gradient.hpp"

namespace hinge::reference {

template <class Scalar>
using Mat12 = Eigen::Matrix<Scalar, 12, 12>;

// Eq. (5): the building blocks of one triangle. Built on T they are omega, M, N, P, Q; built on T~ they
// are the tilde quantities (so Q~ takes omega~: erratum 2 cannot occur).
template <class Scalar>
class BuildingBlocks {
 public:
  explicit BuildingBlocks(const Triangle<Scalar>& t) : t_(t) {}

  Scalar omega(int i, int j) const { return 1 / (t_.h[i] * t_.h[j]); }  // eq. (5)
  Mat3<Scalar> M(int i) const { return t_.n * t_.m[i].transpose(); }    // eq. (5)
  Mat3<Scalar> N(int i) const { return M(i) / (t_.l[i] * t_.l[i]); }    // eq. (5)
  Mat3<Scalar> P(int i, int j) const {                                  // eq. (5), erratum 1
    const int other = 3 - i;                                            // the other hinge vertex: 1 <-> 2
    return omega(i, j) * t_.cos_alpha[other] * M(j).transpose();
  }
  Mat3<Scalar> Q(int j) const { return omega(0, j) * M(j); }  // eq. (5), erratum 2

 private:
  const Triangle<Scalar>& t_;
};

template <class Scalar>
Mat3<Scalar> S(const Mat3<Scalar>& A) {  // eq. (5): S(A) = A + A^T
  return A + A.transpose();
}

template <class Scalar>
Mat12<Scalar> hessian(const Stencil<Scalar>& s) {
  const BuildingBlocks<Scalar> b(s.upper);   // left column of eq. (6)
  const BuildingBlocks<Scalar> bt(s.lower);  // right column of eq. (6): the tilde quantities
  Mat12<Scalar> H = Mat12<Scalar>::Zero();
  auto block = [&H](int i, int j) { return H.template block<3, 3>(3 * i, 3 * j); };

  block(0, 0) = -S(b.Q(0));   // eq. (6) H00
  block(3, 3) = -S(bt.Q(0));  // eq. (6) H33
  // N0 + N~0 is symmetric (proofs/half-hinge.md); its symmetric part, taken explicitly, keeps the
  // rounded diagonal blocks exactly symmetric.
  const Mat3<Scalar> N0_sum = b.N(0) + bt.N(0);
  const Mat3<Scalar> N0_and_Nt0 = (N0_sum + N0_sum.transpose()) / Scalar(2);                           // N0 + N~0
  block(1, 1) = S(b.P(1, 1)) + S(bt.P(1, 1)) - N0_and_Nt0;                                             // eq. (6) H11
  block(2, 2) = S(b.P(2, 2)) + S(bt.P(2, 2)) - N0_and_Nt0;                                             // eq. (6) H22
  block(1, 0) = b.P(1, 0) - b.Q(1);                                                                    // eq. (6) H10
  block(2, 0) = b.P(2, 0) - b.Q(2);                                                                    // eq. (6) H20
  block(1, 3) = bt.P(1, 0) - bt.Q(1);                                                                  // eq. (6) H13
  block(2, 3) = bt.P(2, 0) - bt.Q(2);                                                                  // eq. (6) H23
  block(1, 2) = b.P(1, 2) + b.P(2, 1).transpose() + bt.P(1, 2) + bt.P(2, 1).transpose() + N0_and_Nt0;  // eq. (6) H12
  // H03 = 0 (eq. (6)): left as zero. The remaining blocks by symmetry, H_ji = H_ij^T.
  block(0, 1) = block(1, 0).transpose();
  block(0, 2) = block(2, 0).transpose();
  block(3, 1) = block(1, 3).transpose();
  block(3, 2) = block(2, 3).transpose();
  block(2, 1) = block(1, 2).transpose();
  return H;
}

}  // namespace hinge::reference
