// tests/support/same_results.hpp: bit-for-bit comparison of the certified oracle's results (so +0 and -0
// differ), for the tests of its fast path (tests/oracle/oracle_fast_path_test.cpp,
// tests/properties/oracle_properties.cpp). Each returns "" when the two agree, else the first difference.
#pragma once

#include <bit>
#include <cstdint>
#include <string>

#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::test {

inline bool same_double(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// theta, grad (12), hess (144), and no uncertified output on either side.
inline std::string first_difference(const oracle::CertifiedTheta& a, const oracle::CertifiedTheta& b) {
  if (!same_double(a.theta, b.theta)) return "theta";
  for (int k = 0; k < 12; ++k)
    if (!same_double(a.grad[k], b.grad[k])) return "grad[" + std::to_string(k) + "]";
  for (int k = 0; k < 144; ++k)
    if (!same_double(a.hess[k], b.hess[k])) return "hess[" + std::to_string(k) + "]";
  if (!a.uncertified.empty() || !b.uncertified.empty()) return "uncertified outputs";
  return "";
}

// The energy, the gradient, the Hessian's pattern and values, and no uncertified output on either side.
inline std::string first_difference(const oracle::CertifiedMesh& a, const oracle::CertifiedMesh& b) {
  if (!same_double(a.rounded.energy, b.rounded.energy)) return "energy";
  if (a.rounded.gradient.size() != b.rounded.gradient.size()) return "the gradient's size";
  for (std::size_t i = 0; i < a.rounded.gradient.size(); ++i)
    if (!same_double(a.rounded.gradient[i], b.rounded.gradient[i])) return "gradient[" + std::to_string(i) + "]";
  const auto& A = a.rounded.hessian;
  const auto& B = b.rounded.hessian;
  if (A.rows() != B.rows() || A.nonZeros() != B.nonZeros()) return "the Hessian's pattern";
  for (Eigen::Index c = 0; c < A.outerSize(); ++c) {
    Eigen::SparseMatrix<double>::InnerIterator ia(A, c), ib(B, c);
    for (; ia && ib; ++ia, ++ib)
      if (ia.row() != ib.row() || !same_double(ia.value(), ib.value()))
        return "hessian(" + std::to_string(ia.row()) + "," + std::to_string(c) + ")";
    if (ia || ib) return "the Hessian's pattern in column " + std::to_string(c);
  }
  if (!a.uncertified.empty() || !b.uncertified.empty()) return "uncertified outputs";
  return "";
}

}  // namespace hinge::test
