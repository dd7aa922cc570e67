// A program using the installed library as the README shows: one hinge by the reference, the fast kernel
// and the certified oracle. Exit 0 when the three agree (the tolerance is the test's, stated below).
#include <array>
#include <cmath>
#include <cstdio>

#include "hinge/fast/hinge_kernel.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge/reference/evaluate.hpp"

int main() {
  // x0, x1, x2, x3: a well-shaped hinge folded by about a right angle (docs/contract.md, the stencil).
  const std::array<double, 12> x{0.1, 1.0, 0.2, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.4, 0.1, 1.0};
  const auto reference = hinge::reference::theta_derivatives<double>(x);
  const auto fast = hinge::fast::hinge_derivatives<double>(x);
  const auto certified = hinge::oracle::certified_theta_derivatives(x);
  std::printf("theta: reference %.17g, fast %.17g, oracle %.17g\n", reference.angle.theta, fast.theta, certified.theta);
  // Both methods are within a few units of 2^-53 of the certified value on a well-shaped hinge
  // (docs/testing.md); 64 units leaves room for any compiler and still catches a wrong library.
  const double tolerance = 64 * 0x1p-53 * std::abs(certified.theta);
  const bool agree = std::abs(reference.angle.theta - certified.theta) <= tolerance &&
                     std::abs(fast.theta - certified.theta) <= tolerance;
  return agree ? 0 : 1;
}
