// tests/fast/fast_support.hpp: meshes and helpers shared by the tests of hinge::fast.
#pragma once

#include <Eigen/SparseCore>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include "hinge/core/mesh.hpp"
#include "hinge/core/scalar.hpp"
#include "hinge/reference/evaluate.hpp"

namespace hinge::test {

// The independent high-precision evaluation the per-hinge kernel is measured against: hinge::reference in
// MPFR at 256 bits.
inline reference::ThetaDerivatives<mpfr> exact(const std::array<double, 12>& x) {
  set_mpfr_bits(256);
  return reference::theta_derivatives<mpfr>(x);
}

// Number of random cases: `quick` by default, ten times more with HINGE_TEST_DEPTH=deep.
inline int cases(int quick) {
  const char* depth = std::getenv("HINGE_TEST_DEPTH");
  return (depth && std::string(depth) == "deep") ? 10 * quick : quick;
}

// An n x n grid of vertices, jittered in the plane and bumped out of it (nonzero angles of both signs),
// with both diagonal directions (so that vertex degrees vary).
inline Mesh bumpy_grid(int n, unsigned seed, double amplitude = 1.0) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  Mesh m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.vertices.push_back(
          {i + jitter(rng), j + jitter(rng), amplitude * std::sin(i * 0.9) * std::cos(j * 0.7) + jitter(rng)});
  auto v = [n](int i, int j) { return static_cast<Index>(j * n + i); };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      if ((i + j) % 2) {
        m.faces.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
        m.faces.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
      } else {
        m.faces.push_back({v(i, j), v(i + 1, j), v(i, j + 1)});
        m.faces.push_back({v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  return m;
}

// ||A - B||_F / ||B||_F in units of u, for sparse matrices of any structure (missing entries are 0).
template <class Scalar>
double sparse_units(const Eigen::SparseMatrix<Scalar>& a, const Eigen::SparseMatrix<Scalar>& b, double u) {
  const Eigen::SparseMatrix<Scalar> d = a - b;
  return to_double(Scalar(d.norm() / b.norm())) / u;
}

template <class Vector>
double vector_units(const Vector& a, const Vector& b, double u) {
  using Scalar = typename Vector::Scalar;
  return to_double(Scalar((a - b).norm() / b.norm())) / u;
}

}  // namespace hinge::test
