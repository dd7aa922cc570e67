// oracle/src/fast_path.hpp: the certified oracle's fast path (private to hinge::oracle;
// proofs/oracle-fast-path.md). The exact form of exact_form.hpp evaluated in double-double with a
// rigorous error bound (bounded.hpp), theta's arctangent by a table and a series in the same arithmetic;
// an output is decided when its whole error interval rounds to one double. What it cannot decide (zeros
// by cancellation, ties, values within about 2^-100 of a midpoint, shapes whose cancellation eats the
// double-double's margin, ranges near underflow or overflow) is left to the exact stage and the
// enclosures.
#pragma once

#include <array>

namespace hinge::oracle::detail {

// Outputs in the order theta, grad[0..11], hess[0..143].
inline constexpr int kOutputs = 1 + 12 + 144;

struct FastDecisions {
  std::array<bool, kOutputs> decided{};
  std::array<double, kOutputs> value{};
  int count = 0;  // how many are decided
};

// Decides what it can for the hinge x; decides nothing for a non-finite or possibly degenerate hinge
// (the exact stage then gives the error).
FastDecisions fast_path(const std::array<double, 12>& x);

}  // namespace hinge::oracle::detail
