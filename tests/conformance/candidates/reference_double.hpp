// tests/conformance/candidates/reference_double.hpp: the correct starting point of the deliberately
// wrong candidates beside it: hinge::reference in double, in the layout of hinge/candidate.h.
#pragma once

#include <array>
#include <exception>

#include "hinge/candidate.h"
#include "hinge/reference/evaluate.hpp"

namespace candidates {

inline std::array<double, 12> input(const double x[12]) {
  std::array<double, 12> in;
  for (int i = 0; i < 12; ++i) in[i] = x[i];
  return in;
}

// theta, grad, hess of the reference in double; false when the hinge cannot be evaluated.
inline bool reference_double(const double x[12], double* theta, double grad[12], double hess[144]) {
  try {
    const auto d = hinge::reference::theta_derivatives<double>(input(x), true);
    *theta = d.angle.theta;
    for (int i = 0; i < 12; ++i) grad[i] = d.grad[i];
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) hess[12 * i + j] = d.hess(i, j);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace candidates
