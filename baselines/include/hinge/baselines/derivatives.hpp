// hinge/baselines/derivatives.hpp: what the baseline methods (autodiff.hpp, symbolic.hpp) return, and how
// much of it a call computes. The baselines are theta, grad theta and Hess theta computed the ways a user
// reaches for before reading the paper: automatic differentiation and generated symbolic code, both from
// the atan2 definition of docs/contract.md,
//
//   theta = atan2(((N x Nt) . e0) / |e0|, N . Nt),  e0 = x2 - x1,  N = (x1 - x0) x (x2 - x0),
//   Nt = (x2 - x3) x (x1 - x3),
//
// evaluated in Scalar from the 12 input doubles, with no rescaling and no care for cancellation: the
// study (hinge study) measures what that costs in accuracy, and what the paper's formulas save in time.
#pragma once

#include <Eigen/Core>
#include <array>

namespace hinge::baselines {

// The outputs a call computes: theta; theta and its gradient; all three.
enum class Outputs { theta, gradient, hessian };

template <class Scalar>
struct Derivatives {
  Scalar theta = 0;                     // in (-pi, pi] (-pi, which atan2 gives for a zero numerator of
                                        // negative sign, is reported as +pi, the contract's branch cut)
  Eigen::Matrix<Scalar, 12, 1> grad;    // left zero unless computed
  Eigen::Matrix<Scalar, 12, 12> hess;   // left zero unless computed
};

}  // namespace hinge::baselines
