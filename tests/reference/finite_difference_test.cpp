// grad theta (eq. (4)) and Hess theta (eqs. (5)-(6)) against central finite differences of an independent
// theta (the atan2 definition of docs/contract.md, written out here from the positions), in MPFR at 256
// bits, asserting that the difference shrinks at O(h^2): halving h divides it by 4.
#include <gtest/gtest.h>

#include "hinge/reference/evaluate.hpp"
#include "support/hinges.hpp"
#include "support/tolerance.hpp"

namespace hinge::reference {
namespace {

using Real = mpfr;
constexpr unsigned bits = 256;

// theta straight from docs/contract.md, with no code of the library.
Real theta_of(const std::array<Real, 12>& x) {
  auto p = [&x](int v) { return Vec3<Real>(x[3 * v], x[3 * v + 1], x[3 * v + 2]); };
  const Vec3<Real> N = (p(1) - p(0)).cross(p(2) - p(0)), Nt = (p(2) - p(3)).cross(p(1) - p(3)), e0 = p(2) - p(1);
  return atan2(N.cross(Nt).dot(e0) / e0.norm(), N.dot(Nt));
}

std::array<Real, 12> to_real(const std::array<double, 12>& x) {
  std::array<Real, 12> r;
  for (int i = 0; i < 12; ++i) r[i] = x[i];
  return r;
}

// Central differences with step h: first derivatives, and mixed second derivatives from four points.
Vec12<Real> fd_gradient(const std::array<Real, 12>& x, const Real& h) {
  Vec12<Real> g;
  for (int i = 0; i < 12; ++i) {
    auto plus = x, minus = x;
    plus[i] += h;
    minus[i] -= h;
    g[i] = (theta_of(plus) - theta_of(minus)) / (2 * h);
  }
  return g;
}

Mat12<Real> fd_hessian(const std::array<Real, 12>& x, const Real& h) {
  Mat12<Real> H;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j <= i; ++j) {
      auto at = [&](int si, int sj) {
        auto y = x;
        y[i] += si * h;
        y[j] += sj * h;
        return theta_of(y);
      };
      H(i, j) = H(j, i) = (at(1, 1) - at(1, -1) - at(-1, 1) + at(-1, -1)) / (4 * h * h);
    }
  return H;
}

// The largest coordinate difference: steps are taken relative to it (hinges span 1e-3 to 1e3).
double size(const std::array<double, 12>& x) {
  double s = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < a; ++b)
      for (int c = 0; c < 3; ++c) s = std::max(s, std::abs(x[3 * a + c] - x[3 * b + c]));
  return s;
}

template <class M>
double norm_difference(const M& a, const M& b) {
  return to_double(Real((a - b).norm() / b.norm()));
}

TEST(FiniteDifferences, GradientErrorShrinksQuadratically) {
  set_mpfr_bits(bits);
  for (const auto& x : test::well_shaped_hinges(4, 21, 0)) {
    const auto d = theta_derivatives<Real>(x);
    const auto xr = to_real(x);
    const Real h0 = Real(1e-6) * size(x);  // steps 1e-6, 5e-7, 2.5e-7 of the hinge's size
    double previous = 0;
    for (int k = 0; k < 3; ++k) {
      const Real h = h0 / (1 << k);
      const double error = norm_difference(fd_gradient(xr, h), d.grad);
      // Truncation error C h^2 (rounding at 256 bits is ~1e-71, invisible): halving h divides it by 4,
      // within 10% (the h^4 term is ~h^2 = 1e-12 relative smaller).
      if (k > 0) {
        EXPECT_NEAR(previous / error, 4.0, 0.4) << test::describe(x);
      }
      EXPECT_LT(error, 1e-8) << test::describe(x);
      previous = error;
    }
  }
}

TEST(FiniteDifferences, HessianErrorShrinksQuadratically) {
  set_mpfr_bits(bits);
  for (const auto& x : test::well_shaped_hinges(3, 22, 0)) {
    const auto d = theta_derivatives<Real>(x);
    const auto xr = to_real(x);
    double previous = 0;
    for (int k = 0; k < 3; ++k) {
      const Real h = Real(1e-5) * size(x) / (1 << k);
      const double error = norm_difference(fd_hessian(xr, h), d.hess);
      if (k > 0) {
        EXPECT_NEAR(previous / error, 4.0, 0.4) << test::describe(x);
      }  // O(h^2), as above
      EXPECT_LT(error, 1e-6) << test::describe(x);
      previous = error;
    }
  }
}

// The check is able to fail: a Hessian with one transposed off-diagonal block (the error a missing
// conditional transpose makes) differs from the finite differences by far more than their O(h^2).
TEST(FiniteDifferences, DetectsATransposedBlock) {
  set_mpfr_bits(bits);
  const auto x = test::well_shaped_hinges(1, 23, 0).front();
  auto H = theta_derivatives<Real>(x).hess;
  const Mat3<Real> B = H.block<3, 3>(3, 6);
  H.block<3, 3>(3, 6) = B.transpose();
  H.block<3, 3>(6, 3) = B;
  EXPECT_GT(norm_difference(fd_hessian(to_real(x), Real(1e-5) * size(x)), H), 1e-3);
}

}  // namespace
}  // namespace hinge::reference
