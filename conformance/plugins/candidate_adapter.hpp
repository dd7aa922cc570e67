// The part every one of the project's conformance plugins shares (hinge/candidate.h): copy the 12
// coordinates in, the results out, and turn an exception (a degenerate or non-finite hinge) into the
// "cannot evaluate" return value. A std::invalid_argument (HINGE_ISA naming an unknown or unavailable
// instruction set) is a setting of the host, not of the hinge: it is also printed on standard error, once.
#pragma once

#include <array>
#include <atomic>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "hinge/candidate.h"

namespace hinge::plugins {

// `write(in)` evaluates the hinge `in` and writes the caller's outputs itself.
template <class Write>
int call_candidate_into(const double x[12], Write write) {
  try {
    std::array<double, 12> in;
    for (int i = 0; i < 12; ++i) in[i] = x[i];
    write(in);
    return 0;
  } catch (const std::invalid_argument& e) {
    static std::atomic<bool> said{false};  // once per process, not once per hinge
    if (!said.exchange(true)) std::fprintf(stderr, "hinge candidate plugin: %s\n", e.what());
    return 1;
  } catch (const std::exception&) {
    return 1;
  }
}

// `evaluate(x)` returns the hinge's derivatives; `theta_of(d)` picks theta from them (the reference
// and the fast kernel name it differently); d.grad[i] and d.hess(i, j) are read as doubles and copied out.
template <class Evaluate, class ThetaOf>
int call_candidate(const double x[12], double* theta, double grad[12], double hess[144], Evaluate evaluate,
                   ThetaOf theta_of) {
  return call_candidate_into(x, [&](const std::array<double, 12>& in) {
    const auto d = evaluate(in);
    *theta = theta_of(d);
    for (int i = 0; i < 12; ++i) grad[i] = d.grad[i];
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) hess[12 * i + j] = d.hess(i, j);  // row-major
  });
}

}  // namespace hinge::plugins
