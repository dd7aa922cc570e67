// hinge/oracle/quadratic.hpp: the certified isometric bending term of one hinge (docs/quantities.md,
// "quadratic"; Bergou et al. 2006, Wardetzky et al. 2007): with K the four cotangent weights of the rest hinge
// R and A_bar its two triangles' area,
//     s = sum_j K_j x_j,   psi = (3 k / A_bar) |s|^2,   grad_j psi = 2 c_q K_j s,   Hess = 2 c_q K K^T (x) I_3,
// each output the double nearest the exact value (Ziv's strategy on MPFI enclosures, as oracle.hpp). The
// cotangents are exact rationals over sqrt(N . N) and sqrt(Nt . Nt) (exact.hpp's integers), s is summed over
// the exact differences x_j - x1 (sum K = 0), and the exact zeros are decided exactly: s = 0 at a flat rest
// hinge (X == R, theta_bar = 0); a component of s where every x_j has the same coordinate; K1 or K2 where
// its two cotangents cancel (an integer identity); the Hessian's entries between different axes.
#pragma once

#include <array>
#include <vector>

#include "hinge/oracle/oracle.hpp"

namespace hinge::oracle {

struct CertifiedEnergy {
  double energy = 0;
  std::array<double, 12> grad{};
  std::array<double, 144> hess{};  // row-major
  unsigned bits = 0;               // the working precision the enclosures needed
  std::vector<Uncertified> uncertified;
};

// Throws hinge::InputError for a non-finite coordinate or a degenerate rest triangle (exact_hinge's checks on
// R), hinge::DomainError where an output overflows double. `k` is taken as the exact value of the double.
CertifiedEnergy certified_quadratic(const std::array<double, 12>& x, const std::array<double, 12>& rest, double k,
                                    const Options& options = {});

}  // namespace hinge::oracle
