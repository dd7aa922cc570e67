// The study's one timing method (timing.hpp).
#include "timing.hpp"

#include <algorithm>
#include <cmath>

#include "hinge/fast/hinge_kernel.hpp"

namespace hinge::study::detail {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

}  // namespace

void fast_into(int g, const std::array<double, 12>& x, Slots& out, std::size_t i) {
  if (g == 2) {
    fast::hinge_derivatives_into(x, out.theta[i], &out.grad[12 * i], &out.hess[144 * i]);
    return;
  }
  const fast::HingeDerivatives<double> d = fast::hinge_derivatives<double>(x, false);
  out.theta[i] = d.theta;
  if (g == 1) std::copy(d.grad.begin(), d.grad.end(), out.grad.begin() + static_cast<std::ptrdiff_t>(12 * i));
}

void fast_per_hinge(const double* x, double* theta, double* grad, double* hess) {
  std::array<double, 12> h;
  std::copy(x, x + 12, h.begin());
  try {
    fast::hinge_derivatives_into(h, *theta, grad, hess);
  } catch (...) {  // a hinge fast rejects is the candidate's timing hinge all the same; the slot keeps its values
  }
}

RoundPolicy round_policy(bool quick) {
  RoundPolicy p;
  if (!quick) p.min_rounds = 101, p.min_seconds = 1.0, p.pass_seconds = 1e-3;
  return p;
}

void Rounds::summarize(io::StudyRow& row, int groups) const {
  for (int g = 0; g < 3; ++g) {
    const int from = groups == 1 ? 2 : g;
    row.ns_per_hinge[g] = median(ns[from]);
    row.x_fast[g] = median(ratio[from]);
  }
  row.rounds = ns[2].size();
}

int repeats_for(double seconds, double ns_per_hinge, std::size_t count) {
  const double pass = ns_per_hinge * 1e-9 * static_cast<double>(count);
  if (!(pass > 0)) return 1;
  return static_cast<int>(std::clamp(std::round(seconds / pass), 1.0, 1e6));
}

std::size_t chunk_for(double seconds, double ns_per_hinge, std::size_t n) {
  if (!(ns_per_hinge > 0)) return n;
  return static_cast<std::size_t>(std::clamp(std::round(seconds / (ns_per_hinge * 1e-9)), 1.0, double(n)));
}

std::vector<std::pair<std::string, std::string>> timing_description(std::size_t hinges, bool builtin,
                                                                    const RoundPolicy& policy) {
  return {
      {"call",
       "per hinge, one call of the row's public per-hinge function (fast in double: "
       "hinge::fast::hinge_derivatives_into; an outside row: its hinge_candidate through hinge/candidate.h, "
       "or its Python callable on the whole batch), its outputs written as doubles into slot i of the caller's "
       "arrays; types other than double round each output to double there"},
      {"hinges", std::to_string(hinges) +
                     (builtin ? " seeded well-shaped hinges (well_shaped_hinges(256, 2013))"
                              : " of the input hinges, the categories in turn") +
                     "; a row whose pass would not fit its budget times the first ones only, and fast with it"},
      {"results",
       "arrays of theta (n), gradients (12 n) and Hessians (144 n) doubles, one slot per hinge, "
       "written by every call"},
      {"rounds", "at least " + std::to_string(policy.min_rounds) + " rounds and " +
                     std::to_string(policy.min_seconds).substr(0, 4) +
                     " s of the row's passes; per round and output group the row's pass and fast's pass in double "
                     "over the same hinges back to back in one process, their order alternating; each pass (repeated "
                     "over its hinges when short) lasting about " +
                     std::to_string(static_cast<int>(policy.pass_seconds * 1e6)) + " us"},
      {"ns_per_hinge", "the median of the row's passes"},
      {"x_fast", "the median of the per-round ratios row / fast"},
      {"outside",
       "the candidate's process times both passes (fast: this program's kernel, which the process "
       "shares as a fork of it); a Python callable is timed per hinge over its batches, beside "
       "fast's pass in the same process"},
      {"threads", "one"},
  };
}

}  // namespace hinge::study::detail
