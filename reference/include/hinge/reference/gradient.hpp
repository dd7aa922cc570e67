// hinge/reference/gradient.hpp: grad theta, eq. (4) (proofs/gradient.md). Labels: stencil.hpp.
//
//   grad_x0 theta = -n / h0                               grad_x3 theta = -n~ / h~0
//   grad_x1 theta = cos(alpha2)/h1 n + cos(alpha~2)/h~1 n~
//   grad_x2 theta = cos(alpha1)/h2 n + cos(alpha~1)/h~2 n~
//
// Variables: x0, x1, x2, x3 (12); the gradient is a column of 12.
#pragma once

#include "hinge/reference/stencil.hpp"

namespace hinge::reference {

template <class Scalar>
using Vec12 = Eigen::Matrix<Scalar, 12, 1>;

template <class Scalar>
Vec12<Scalar> gradient(const Stencil<Scalar>& s) {
  const Triangle<Scalar>& T = s.upper;
  const Triangle<Scalar>& Tt = s.lower;  // paper labels: vertex 1 is x1, vertex 2 is x2
  Vec12<Scalar> g;
  g.template segment<3>(0) = -T.n / T.h[0];                                                     // eq. (4)
  g.template segment<3>(3) = T.cos_alpha[2] / T.h[1] * T.n + Tt.cos_alpha[2] / Tt.h[1] * Tt.n;  // eq. (4)
  g.template segment<3>(6) = T.cos_alpha[1] / T.h[2] * T.n + Tt.cos_alpha[1] / Tt.h[2] * Tt.n;  // eq. (4)
  g.template segment<3>(9) = -Tt.n / Tt.h[0];                                                   // eq. (4)
  return g;
}

}  // namespace hinge::reference
