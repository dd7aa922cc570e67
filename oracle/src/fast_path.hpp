// oracle/src/fast_path.hpp: the certified oracle's fast path (private to hinge::oracle;
// proofs/oracle-fast-path.md). The exact form of exact_form.hpp evaluated in double-double with a
// rigorous error bound (bounded.hpp), theta's arctangent by a table and a series in the same arithmetic;
// an output is decided when its whole error interval rounds to one double. What it cannot decide (zeros
// by cancellation, ties, values within about 2^-100 of a midpoint, shapes whose cancellation eats the
// double-double's margin, ranges near underflow or overflow) is left to the exact stage and the
// enclosures.
#pragma once

#include <array>
#include <optional>

#include "bounded.hpp"

namespace hinge::oracle::detail {

// Outputs in the order theta, grad[0..11], hess[0..143].
inline constexpr int kOutputs = 1 + 12 + 144;

struct FastDecisions {
  std::array<bool, kOutputs> decided{};
  std::array<double, kOutputs> value{};
  int count = 0;  // how many are decided
};

// Whether every real within v.err of v.hi + v.lo, times 2^scale, rounds to one double (then `out`, v.hi
// 2^scale; an exact zero is +0): the interval lies strictly inside v.hi's rounding interval, away from
// underflow and overflow (|v.hi| in [2^-900, 2^901), |v.hi 2^scale| in [2^-1021, 2^1022)).
bool decide(const Bounded& v, int scale, double& out);

// Decides what it can for the hinge x; decides nothing for a non-finite or possibly degenerate hinge
// (the exact stage then gives the error).
FastDecisions fast_path(const std::array<double, 12>& x);

// One hinge in the bounded arithmetic, in the units of its coordinates (the mesh's fast path,
// mesh_fast_path.cpp): theta and t = tan(theta / 2) (exact zeros when exactly flat), the coefficient
// a = 3 |e0|^2 / A of Algorithm 1 (A the two triangles' area over 3), and with `with_derivatives` grad theta
// and Hess theta (row-major). Nothing where fast_path would decide nothing, and where Y is not certainly
// nonzero unless exactly flat (the branch cut included).
struct BoundedHinge {
  Bounded theta, tan_half, a;
  std::array<Bounded, 12> grad;
  std::array<Bounded, 144> hess;
};
std::optional<BoundedHinge> bounded_hinge(const std::array<double, 12>& x, bool with_derivatives);

}  // namespace hinge::oracle::detail
