// hinge/oracle/exact.hpp: the exact stage of the certified oracle. Every polynomial part of a hinge
// (edge vectors, cross and dot products) is computed in exact integer arithmetic (GMP), and eqs. (4)-(6)
// are rewritten so that theta's gradient and Hessian are exact rationals over one common square root:
//
//     grad theta = g / (g_den |e0|) * 2^F          Hess theta = h / (h_den |e0|) * 2^(2F)
//     theta      = atan2(Y / |e0|, X)               X = N . Nt,  Y = (N x Nt) . e0
//
// with integers g, g_den, h, h_den, X, Y and |e0| = sqrt(s), s = e0 . e0 an integer. Zero and sign
// decisions (degenerate triangles, an exactly zero output, the branch cut theta = +pi) are therefore
// exact; only the last step (one square root, one quotient, one arctangent) is approximated, in
// oracle.hpp (src/certify.cpp). The derivation, block by block, is in oracle/README.md ("The exact form of eqs.
// (4)-(6)").
//
//                 x0                 upper triangle T = (x0, x1, x2), N = (x1 - x0) x (x2 - x0)
//          e1   /  \   e2            e0 = x2 - x1, e1 = x0 - x2, e2 = x1 - x0
//            x1 ---> x2   e0         lower triangle (x3, x2, x1), Nt = (x2 - x3) x (x1 - x3)
//          et2  \  /  et1            et1 = x3 - x2, et2 = x1 - x3 (the paper's e~1, e~2; e~0 = e0)
//                x3
//
// Variables: x0, x1, x2, x3 (12); gradient 12, Hessian 144 row-major (docs/contract.md).
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstddef>

namespace hinge::oracle {

using Int = mpz_class;

// The 12 input coordinates as integers over one power of two: coordinate i is exactly X[i] * 2^-F.
// Any finite doubles fit (the integers then have up to about 2100 bits).
struct ScaledHinge {
  std::array<Int, 12> X;
  long F = 0;
};

// Exact conversion of 12 finite doubles (throws hinge::InputError naming a non-finite coordinate).
ScaledHinge scale_exactly(const std::array<double, 12>& x);

// The same hinge with every coordinate multiplied by 2^extra (F grows by `extra`): room to perturb a
// coordinate by +-1 (= 2^-(F + extra)) for finite differences.
ScaledHinge refine(const ScaledHinge& h, unsigned long extra);

struct ExactHinge {
  long F = 0;              // integer lengths * 2^-F are the true lengths
  Int s;                   // e0 . e0 (> 0)
  Int nn, tt;              // N . N, Nt . Nt (> 0): (2A)^2 of the upper and lower triangle
  Int X, Y;                // N . Nt and (N x Nt) . e0: theta = atan2(Y / sqrt(s), X)
  std::array<Int, 12> g;   // grad theta = g / (g_den sqrt(s)) 2^F, eq. (4)
  Int g_den;               // nn tt (> 0)
  std::array<Int, 144> h;  // Hess theta = h / (h_den sqrt(s)) 2^(2F), eqs. (5)-(6), row-major
  Int h_den;               // 2 nn^2 tt^2 s (> 0)
  bool has_hessian = false;

  // Size in bits of the largest integer above: how wide the exact polynomial parts are.
  std::size_t max_bits() const;
};

// Validates the hinge exactly (the checks and messages of hinge::reference::prepare_hinge: a zero-length
// hinge edge, a triangle of exactly zero area; throws hinge::InputError) and computes its exact form.
ExactHinge exact_hinge(const ScaledHinge& x, bool with_hessian = true);
ExactHinge exact_hinge(const std::array<double, 12>& x, bool with_hessian = true);

// Whether theta of `a` equals theta of `b`, decided exactly: the same signs of sin (Y) and cos (X), and
// X_a^2 nn_b tt_b == X_b^2 nn_a tt_a (equal cosines).
bool same_angle(const ExactHinge& a, const ExactHinge& b);

}  // namespace hinge::oracle
