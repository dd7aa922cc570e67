// The study's shared inputs (prepared.hpp).
#include "prepared.hpp"

#include <algorithm>
#include <cmath>

#include "hinge/core/errors.hpp"

namespace hinge::study::detail {
namespace {

// L, the longest of the five edge vectors (to a few units: it only scales an error where f* == 0).
double longest_edge(const std::array<double, 12>& x) {
  const int edges[5][2] = {{2, 1}, {0, 1}, {0, 2}, {3, 1}, {3, 2}};
  double longest = 0;
  for (const auto& e : edges) {
    const int a = 3 * e[0], b = 3 * e[1];
    longest = std::max(longest, std::hypot(x[a] - x[b], x[a + 1] - x[b + 1], x[a + 2] - x[b + 2]));
  }
  return longest;
}

double norm(const double* v, std::size_t n) {
  double s = 0;
  for (std::size_t i = 0; i < n; ++i) s = std::hypot(s, v[i]);
  return s;
}

}  // namespace

Prepared::Prepared(std::vector<StudyHinge> all, std::vector<std::array<double, 12>> timing_hinges,
                   const ProgressFn& progress)
    : timing(std::move(timing_hinges)) {
  std::map<std::string, std::vector<std::size_t>> by_category;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (progress) progress("certifying", i, all.size());
    try {
      oracle::Options slow;  // stages 1 and 2 alone: what the oracle's own row, fast path on, is measured against
      slow.fast_path = false;
      certified.push_back(oracle::certified_theta_derivatives(all[i].x, slow));
    } catch (const InputError&) {
      ++skipped;
      continue;
    } catch (const DomainError&) {
      ++skipped;
      continue;
    }
    const oracle::CertifiedTheta& c = certified.back();
    const double L = longest_edge(all[i].x);
    // J_theta = grad theta, J_grad = Hess theta; the Hessian is never exactly zero on a valid hinge.
    scale.push_back({L * norm(c.grad.data(), 12), L * norm(c.hess.data(), 144), 0});
    if (!by_category.count(all[i].category)) categories.push_back(all[i].category);
    by_category[all[i].category].push_back(hinges.size());
    hinges.push_back(std::move(all[i]));
  }
  if (progress) progress("certifying", all.size(), all.size());
  if (hinges.empty()) throw InputError("no hinge of the input could be certified (all degenerate or invalid)");
  for (std::size_t round = 0; order.size() < hinges.size(); ++round)
    for (const auto& c : categories)
      if (round < by_category[c].size()) order.push_back(by_category[c][round]);
  if (timing.empty())  // the user's own hinges: up to 256 of them, spread over the categories
    for (std::size_t k = 0; k < order.size() && timing.size() < 256; ++k) timing.push_back(hinges[order[k]].x);
}

const std::optional<reference::ThetaDerivatives<mpfr>>& Prepared::wide(std::size_t i, unsigned bits) const {
  auto& values = wide_[bits];
  if (values.empty()) values.resize(hinges.size());
  set_mpfr_bits(bits);
  if (!values[i]) {
    try {
      values[i].emplace(reference::theta_derivatives<mpfr>(hinges[i].x, true));
    } catch (const std::exception&) {
      values[i].emplace(std::nullopt);
    }
  }
  return *values[i];
}

}  // namespace hinge::study::detail
