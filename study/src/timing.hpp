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
#include <functional>
#include <memory>
#include <optional>
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

// ns per hinge of `repeats` passes of `call(i mod n)` for i in [begin, begin + count), after one call not
// timed: the rows take turns, so each pass starts with another row's code and data in the caches and the
// branch predictors, which a program calling one kernel in a loop does not see (a row of large code, as
// autodiff's, measured 10-30% slower without it).
template <class Call>
double timed_pass(std::size_t begin, std::size_t count, std::size_t n, int repeats, Call&& call) {
  call(begin % n);
  const auto start = Clock::now();
  for (int r = 0; r < repeats; ++r)
    for (std::size_t i = begin; i < begin + count; ++i) call(i % n);
  return 1e9 * seconds_since(start) / static_cast<double>(count * static_cast<std::size_t>(repeats));
}

// fast in double for output group g (0 theta, 1 theta and gradient, 2 all three) into slot i: the call every
// row is compared with (g == 2: hinge::fast::hinge_derivatives_into).
void fast_into(int g, const std::array<double, 12>& x, Slots& out, std::size_t i);
// The same, all three, as hinge/conformance/plugin.hpp's Plugin::PerHinge (the outside rows' comparison).
void fast_per_hinge(const double* x, double* theta, double* grad, double* hess);

// How long a row's rounds go on.
struct RoundPolicy {
  int min_rounds = 31;
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
  // The medians into the row (ns_per_hinge, x_fast, rounds); `groups` 1: the three are group 2's.
  void summarize(io::StudyRow& row, int groups = 3) const;
};

// Passes of `repeats` needed for a pass of about `seconds` at `ns_per_hinge` over `count` hinges.
int repeats_for(double seconds, double ns_per_hinge, std::size_t count);
// The hinges a pass of about `seconds` takes at `ns_per_hinge`: 1 .. n.
std::size_t chunk_for(double seconds, double ns_per_hinge, std::size_t n);

// A row's timing, a round at a time: run() gives every row its rounds in turn, so that each row's rounds
// spread over the whole timing phase and the host's load, which changes from second to second, touches
// every row alike. round(r) runs round r; done() once the policy is met, or the row's budget spent (after
// at least 3 rounds); finish(row) writes the medians.
struct RowTimer {
  std::function<void(int)> round;
  std::function<bool()> done;
  std::function<void(io::StudyRow&)> finish;
};

// A row and its timer.
struct Measured {
  io::StudyRow row;
  std::optional<RowTimer> timer;
};

// Rounds of `row_pass(g, begin, count, repeats)` against `fast_pass(g, begin, count, repeats)` (each
// returning ns per hinge over hinges begin .. begin + count - 1, modulo the n hinges) for the groups (1: the
// three groups are one call, timed as group 2), back to back, their order alternating from round to round.
// A pass lasts about policy.pass_seconds: a row slower than that times a chunk of the hinges per round, the
// next chunk the next round, fast the same chunk beside it; a faster one repeats them all. `budget`: seconds
// of this row's rounds at most (after 3). `same`: the row is fast in double itself (its ratio is 1).
template <class RowPass, class FastPass>
RowTimer round_timer(RowPass row_pass, FastPass fast_pass, std::size_t n, int groups, const RoundPolicy& policy,
                     double budget, bool same) {
  struct State {
    Rounds rounds;
    std::array<int, 3> row_repeats{1, 1, 1}, fast_repeats{1, 1, 1};
    std::array<std::size_t, 3> chunk{};
    double spent = 0, row_spent = 0;
    int count = 0;
    bool ready = false;
  };
  auto state = std::make_shared<State>();
  const int first = groups == 1 ? 2 : 0;
  RowTimer t;
  t.round = [=](int r) {
    State& st = *state;
    const auto start = Clock::now();
    if (!st.ready) {  // a first pass of each sets the chunk and the repeats (and warms up)
      for (int g = first; g < 3; ++g) {
        const double row_ns = row_pass(g, 0, std::min<std::size_t>(n, 4), 1);
        st.chunk[g] = chunk_for(policy.pass_seconds, row_ns, n);
        st.row_repeats[g] = repeats_for(policy.pass_seconds, row_ns, st.chunk[g]);
        if (!same) st.fast_repeats[g] = repeats_for(policy.pass_seconds, fast_pass(g, 0, st.chunk[g], 1), st.chunk[g]);
      }
      st.ready = true;
    }
    for (int g = first; g < 3; ++g) {
      const std::size_t begin = (static_cast<std::size_t>(st.count) * st.chunk[g]) % n;
      double row_ns = 0, fast_ns = 0;
      const auto pass_start = Clock::now();
      if (same) {
        row_ns = fast_ns = row_pass(g, begin, st.chunk[g], st.row_repeats[g]);
      } else if (r % 2) {
        fast_ns = fast_pass(g, begin, st.chunk[g], st.fast_repeats[g]);
        row_ns = row_pass(g, begin, st.chunk[g], st.row_repeats[g]);
      } else {
        row_ns = row_pass(g, begin, st.chunk[g], st.row_repeats[g]);
        fast_ns = fast_pass(g, begin, st.chunk[g], st.fast_repeats[g]);
      }
      st.row_spent += seconds_since(pass_start) * row_ns / (row_ns + fast_ns);
      st.rounds.add(g, row_ns, fast_ns);
    }
    ++st.count;
    st.spent += seconds_since(start);
  };
  t.done = [=] {
    const State& st = *state;
    return (st.count >= policy.min_rounds && st.row_spent >= policy.min_seconds) ||
           (st.count >= 3 && st.spent >= budget);
  };
  t.finish = [=](io::StudyRow& row) { state->rounds.summarize(row, groups); };
  return t;
}

// study.json's "timing": how every row was timed.
std::vector<std::pair<std::string, std::string>> timing_description(std::size_t hinges, bool builtin,
                                                                    const RoundPolicy& policy);

}  // namespace hinge::study::detail
