// Certified expectations and the comparison of a candidate's outputs (hinge/conformance/grading.hpp).
#include "hinge/conformance/grading.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

namespace hinge::conformance {
namespace {

constexpr double u = 0x1p-53;
constexpr double infinity = std::numeric_limits<double>::infinity();
using oracle::scaled_norm;

const double* group_data(const CertifiedTheta& v, int g) {
  return g == 0 ? &v.theta : g == 1 ? v.grad.data() : v.hess.data();
}
const double* group_data(const CandidateResult& v, int g) {
  return g == 0 ? &v.theta : g == 1 ? v.grad.data() : v.hess.data();
}
constexpr std::size_t group_size[3] = {1, 12, 144};

// The largest magnitude, NaN when a value is NaN.
template <class Values>
double largest_magnitude(const Values& values) {
  double largest = 0;
  for (const double v : values)
    if (!(std::fabs(v) <= largest)) largest = std::isnan(v) ? v : std::fabs(v);
  return largest;
}

}  // namespace

Expected expected(const Case& c) {
  oracle::ConditionedTheta t = oracle::certified_with_conditioning(c.x);
  return {c, std::move(t.values), t.conditioning};
}

double normwise_error(const double* candidate, const double* certified, std::size_t n, double scale_if_zero) {
  std::array<double, 144> difference{};
  if (n > difference.size()) throw std::invalid_argument("normwise_error: at most 144 values");
  for (std::size_t i = 0; i < n; ++i) difference[i] = candidate[i] - certified[i];
  const double size = scaled_norm(certified, n);
  const double normalizer = size > 0 ? size : scale_if_zero;
  const double d = scaled_norm(difference.data(), n);
  return d == 0 ? 0.0 : normalizer > 0 && std::isfinite(d) ? d / normalizer / u : infinity;
}

double symmetric_frobenius(const Eigen::SparseMatrix<double>& upper) {
  const double largest =
      largest_magnitude(std::span<const double>(upper.valuePtr(), static_cast<std::size_t>(upper.nonZeros())));
  if (largest == 0 || !std::isfinite(largest)) return largest;
  double sum = 0;
  for (Eigen::Index c = 0; c < upper.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(upper, c); it; ++it) {
      const double s = it.value() / largest;
      sum += (it.row() == it.col() ? 1 : 2) * (s * s);
    }
  return largest * std::sqrt(sum);
}

double hessian_kappa_sum(const CertifiedMesh& m) {
  const double size = symmetric_frobenius(m.rounded.hessian);
  return size > 0 ? m.hessian_contributions / size : 1.0;
}

double gradient_kappa_sum(const CertifiedMesh& m) {
  const double size = scaled_norm(m.rounded.gradient.data(), m.rounded.gradient.size());
  return size > 0 ? m.gradient_contributions / size : 1.0;
}

MeshComparison compare_mesh_hessian(const CertifiedMesh& m, const Eigen::SparseMatrix<double>& candidate_upper) {
  const Eigen::SparseMatrix<double> difference = candidate_upper - m.rounded.hessian;  // over the union of patterns
  const double size = symmetric_frobenius(m.rounded.hessian);
  MeshComparison c;
  c.kappa_sum = hessian_kappa_sum(m);
  c.error = symmetric_frobenius(difference) / (size > 0 ? size : 1) / u;
  c.tolerance = mesh_base * c.kappa_sum;
  c.pass = std::isfinite(c.error) && c.error <= c.tolerance;
  return c;
}

MeshComparison compare_mesh_gradient(const CertifiedMesh& m, const std::vector<double>& candidate) {
  const std::vector<double>& want = m.rounded.gradient;
  if (candidate.size() != want.size()) throw std::invalid_argument("compare_mesh_gradient: sizes differ");
  std::vector<double> difference(want.size());
  for (std::size_t i = 0; i < want.size(); ++i) difference[i] = candidate[i] - want[i];
  const double size = scaled_norm(want.data(), want.size());
  MeshComparison c;
  c.kappa_sum = gradient_kappa_sum(m);
  c.error = scaled_norm(difference.data(), difference.size()) / (size > 0 ? size : 1) / u;
  c.tolerance = mesh_base * c.kappa_sum;
  c.pass = std::isfinite(c.error) && c.error <= c.tolerance;
  return c;
}

CaseOutcome compare(const Expected& e, const CandidateResult& r, const Policy& policy) {
  CaseOutcome o;
  o.id = e.input.id;
  o.category = e.input.category;
  o.status = r.status;
  o.kappa = e.conditioning.kappa;
  for (int g = 0; g < 3; ++g) o.tolerance[g] = policy.base + policy.c * o.kappa[g];
  if (r.status != CandidateResult::Status::ok) {
    o.error = {infinity, infinity, infinity};
    o.ratio = infinity;
    return o;
  }
  o.ratio = -1;
  for (int g = 0; g < 3; ++g) {
    const double* want = group_data(e.values, g);
    const double* got = group_data(r, g);
    std::array<double, 144> difference{};
    int largest = 0;
    for (std::size_t i = 0; i < group_size[g]; ++i) {
      difference[i] = got[i] - want[i];
      if (std::fabs(difference[i]) > std::fabs(difference[largest]) || std::isnan(difference[i]))
        largest = static_cast<int>(i);
    }
    o.error[g] = normwise_error(got, want, group_size[g], e.conditioning.scale[g]);
    const double ratio = o.error[g] / o.tolerance[g];
    if (ratio > o.ratio) {
      o.ratio = ratio;
      o.group = g;
      o.entry = largest;
      o.expected_value = want[largest];
      o.candidate_value = got[largest];
    }
  }
  o.pass = o.ratio <= 1;
  bool equal = true;
  for (int g = 0; g < 3; ++g)
    for (std::size_t i = 0; i < group_size[g]; ++i) equal = equal && group_data(r, g)[i] == group_data(e.values, g)[i];
  const double worst = std::max({o.error[0], o.error[1], o.error[2]});
  o.tier = !o.pass      ? Tier::fail
           : equal      ? Tier::correctly_rounded
           : worst <= 1 ? Tier::faithful
           : worst <= 4 ? Tier::four_units
                        : Tier::policy;
  return o;
}

const char* tier_name(Tier t) {
  switch (t) {
    case Tier::correctly_rounded: return "correctly-rounded";
    case Tier::faithful: return "faithful";
    case Tier::four_units: return "4u";
    case Tier::policy: return "policy";
    case Tier::fail: return "fail";
  }
  return "?";
}

}  // namespace hinge::conformance
