// The one way every row of the study is timed (study.json's "timing"; docs/study.md, "Times"): the same
// hinges, the same call pattern (per hinge one call of the row's public per-hinge function, its outputs
// written as doubles into slot i of the caller's arrays), and rounds in which the row's pass and fast's
// pass in double over the same hinges run back to back in one process, their order alternating. A row's
// time is the median of its passes; its ratio to fast the median of the per-round ratios, which the host's
// drift (its clock moves by a third from hour to hour) touches alike.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "hinge/io/study_json.hpp"

namespace hinge::study::detail {

// The caller's arrays: theta, then 12 gradient and 144 Hessian entries per hinge (row-major), as a
// program holding many hinges' results lays them out.
struct Slots {
  explicit Slots(std::size_t n) : theta(n), grad(12 * n), hess(144 * n) {}
  std::vector<double> theta, grad, hess;
};

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// ns per hinge of `repeats` passes of `call(i)` over hinges 0 .. count - 1.
template <class Call>
double timed_pass(std::size_t count, int repeats, Call&& call) {
  const auto start = Clock::now();
  for (int r = 0; r < repeats; ++r)
    for (std::size_t i = 0; i < count; ++i) call(i);
  return 1e9 * seconds_since(start) / static_cast<double>(count * static_cast<std::size_t>(repeats));
}

// fast in double for output group g (0 theta, 1 theta and gradient, 2 all three) into slot i: the call every
// row is compared with (g == 2: hinge::fast::hinge_derivatives_into).
void fast_into(int g, const std::array<double, 12>& x, Slots& out, std::size_t i);
// The same, all three, as hinge/conformance/plugin.hpp's Plugin::PerHinge (the outside rows' comparison).
void fast_per_hinge(const double* x, double* theta, double* grad, double* hess);

// How long a row's rounds go on.
struct RoundPolicy {
  int min_rounds = 11;
  double min_seconds = 0.15;   // of the row's passes, all groups
  double pass_seconds = 5e-4;  // a pass's target length (short passes repeated over the same hinges)
};
RoundPolicy round_policy(bool quick);

// The rounds of one row, per group: the row's ns per hinge and its ratio to fast's, round by round.
struct Rounds {
  std::array<std::vector<double>, 3> ns, ratio;
  void add(int g, double row_ns, double fast_ns) {
    ns[g].push_back(row_ns);
    ratio[g].push_back(row_ns / fast_ns);
  }
  // The medians into the row (ns_per_hinge, x_fast, rounds).
  void summarize(io::StudyRow& row) const;
};

// Passes of `repeats` needed for a pass of about `seconds` at `ns_per_hinge` over `count` hinges.
int repeats_for(double seconds, double ns_per_hinge, std::size_t count);

// Rounds of `row_pass(g, repeats)` against `fast_pass(g, repeats)` (each returning ns per hinge) for the
// groups `groups` (1: the three groups are one call, timed as group 2), until the policy is met or
// `deadline` passes (at least 3 rounds).
template <class RowPass, class FastPass>
Rounds time_rounds(RowPass&& row_pass, FastPass&& fast_pass, std::size_t count, int groups, const RoundPolicy& policy,
                   Clock::time_point deadline) {
  Rounds rounds;
  std::array<int, 3> row_repeats{1, 1, 1}, fast_repeats{1, 1, 1};
  const int first = groups == 1 ? 2 : 0;
  for (int g = first; g < 3; ++g) {  // a first pass of each sets the repeats (and warms up)
    row_repeats[g] = repeats_for(policy.pass_seconds, row_pass(g, 1), count);
    fast_repeats[g] = repeats_for(policy.pass_seconds, fast_pass(g, 1), count);
  }
  double spent = 0;
  for (int r = 0;; ++r) {
    if (r >= policy.min_rounds && spent >= policy.min_seconds) break;
    if (r >= 3 && Clock::now() > deadline) break;
    const auto start = Clock::now();
    for (int g = first; g < 3; ++g) {
      double row_ns = 0, fast_ns = 0;
      if (r % 2) {
        fast_ns = fast_pass(g, fast_repeats[g]);
        row_ns = row_pass(g, row_repeats[g]);
      } else {
        row_ns = row_pass(g, row_repeats[g]);
        fast_ns = fast_pass(g, fast_repeats[g]);
      }
      rounds.add(g, row_ns, fast_ns);
    }
    spent += seconds_since(start) / 2;
  }
  if (groups == 1)
    for (int g = 0; g < 2; ++g) rounds.ns[g] = rounds.ns[2], rounds.ratio[g] = rounds.ratio[2];
  return rounds;
}

// study.json's "timing": how every row was timed.
std::vector<std::pair<std::string, std::string>> timing_description(std::size_t hinges, bool builtin,
                                                                    const RoundPolicy& policy);

}  // namespace hinge::study::detail
