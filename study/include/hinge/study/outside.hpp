// hinge/study/outside.hpp: an implementation from outside the project as a row of the study (`hinge study
// --plugin LIB.so`, hinge.study(candidates=...)): measured like the project's rows (its outputs against the
// certified ones), timed by the study's one method (study.json's "timing") in its own process, marked
// "outside" in study.json.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "hinge/io/eval_output.hpp"

namespace hinge::study {

// An outside row's rounds: per round, the candidate's ns per hinge and fast's in double, back to back on the
// same hinges; or why there are none.
struct OutsideTiming {
  std::vector<std::array<double, 2>> rounds;
  std::string error;  // a crash, a time-out, a nonzero return, an exception; "" when timed
};

struct Outside {
  std::string label;  // the row's "method"
  // The candidate's outputs for each hinge, in order: ok, nonfinite, missing (a NaN: not evaluated) or error
  // (it returned nonzero, raised, crashed or timed out on that hinge).
  std::function<std::vector<io::EvalOutput>(const std::vector<std::array<double, 12>>&)> evaluate;
  // `rounds` rounds of a pass of the candidate over `hinges` (one call per hinge writing into the caller's
  // arrays, or the callable on the batch) and a pass of fast over the same hinges, in one process.
  std::function<OutsideTiming(const std::vector<std::array<double, 12>>&, int rounds)> time;
};

// `rounds` rounds of `pass(hinges)` (a candidate's pass over the hinges, ns per hinge, timed by the caller: a
// Python callable on the whole batch) and a pass of fast in double over the same hinges into the caller's
// arrays, back to back in this process, their order alternating: an Outside's `time` for candidates that run
// in this process.
OutsideTiming time_beside_fast(const std::function<double(const std::vector<std::array<double, 12>>&)>& pass,
                               const std::vector<std::array<double, 12>>& hinges, int rounds);

// A plugin's hinge_candidate (hinge/candidate.h; or `symbol`), loaded and called in a child process by
// hinge::conformance::Plugin as `hinge conform --plugin` loads it: a crash or a time-out fails that hinge, or
// the row's timing, not the study. Label: `label`, or the library's file name. Throws
// hinge::conformance::PluginError when the library cannot be loaded.
Outside plugin_candidate(const std::string& path, const std::string& symbol = "hinge_candidate",
                         const std::string& label = "");

}  // namespace hinge::study
