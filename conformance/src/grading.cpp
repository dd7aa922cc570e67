// Certified expectations and the comparison of a candidate's outputs (hinge/conformance/grading.hpp).
#include "hinge/conformance/grading.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

namespace hinge::conformance {
namespace {

constexpr double mesh_unit = 0x1p-53;  // the mesh comparisons: units of 2^-53
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

double normwise_error(const double* candidate, const double* certified, std::size_t n, double scale_if_zero, double u) {
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
  c.error = symmetric_frobenius(difference) / (size > 0 ? size : 1) / mesh_unit;
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
  c.error = scaled_norm(difference.data(), difference.size()) / (size > 0 ? size : 1) / mesh_unit;
  c.tolerance = mesh_base * c.kappa_sum;
  c.pass = std::isfinite(c.error) && c.error <= c.tolerance;
  return c;
}

const char* group_name(const Grading& grading, int g) {
  return (grading.energy ? energy_group_names : group_names)[static_cast<std::size_t>(g)];
}

double unit_roundoff(Dtype d) { return d == Dtype::float32 ? 0x1p-24 : 0x1p-53; }

const char* dtype_name(Dtype d) { return d == Dtype::float32 ? "float32" : "float64"; }

Dtype parse_dtype(const std::string& name) {
  if (name == "float64") return Dtype::float64;
  if (name == "float32") return Dtype::float32;
  throw std::invalid_argument("unknown dtype '" + name + "' (expected \"float64\" or \"float32\")");
}

// 2^-20 (float64) or 2^-8 (float32) relative, in units of u: the formula is right to about a third of the
// format's digits.
double approximate_bound(Dtype d) { return d == Dtype::float32 ? 0x1p16 : 0x1p33; }

CandidateResult rounded_to(Dtype d, CandidateResult r) {
  if (d == Dtype::float64) return r;
  const auto to_float = [](double& v) { v = static_cast<double>(static_cast<float>(v)); };
  to_float(r.theta);
  for (double& v : r.grad) to_float(v);
  for (double& v : r.hess) to_float(v);
  return r;
}

CaseOutcome compare(const Expected& e, const CandidateResult& candidate, const Grading& grading) {
  const double unit = unit_roundoff(grading.dtype);
  CaseOutcome o;
  o.id = e.input.id;
  o.category = e.input.category;
  o.status = candidate.status;
  o.kappa = e.conditioning.kappa;
  for (int g = 0; g < 3; ++g) o.tolerance[g] = grading.policy.base + grading.policy.c * o.kappa[g];
  if (candidate.status != CandidateResult::Status::ok) {
    o.error = {infinity, infinity, infinity};
    for (int g = 0; g < 3; ++g)
      if (!grading.given[g]) o.error[g] = std::numeric_limits<double>::quiet_NaN();
    o.ratio = infinity;
    return o;
  }
  const CandidateResult r = rounded_to(grading.dtype, candidate);
  o.ratio = -1;
  bool equal = true, approximate = true;
  double worst = 0;
  for (int g = 0; g < 3; ++g) {
    if (!grading.given[g]) {
      o.error[g] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    const double* want = group_data(e.values, g);
    const double* got = group_data(r, g);
    int largest = 0;
    for (std::size_t i = 0; i < group_size[g]; ++i) {
      const double difference = got[i] - want[i];
      if (std::fabs(difference) > std::fabs(got[largest] - want[largest]) || std::isnan(difference))
        largest = static_cast<int>(i);
      equal = equal && got[i] == want[i];
    }
    o.error[g] = normwise_error(got, want, group_size[g], e.conditioning.scale[g], unit);
    worst = std::max(worst, o.error[g]);
    approximate = approximate && o.error[g] <= approximate_bound(grading.dtype) * (1 + o.kappa[g]);
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
  o.tier = o.pass        ? (equal        ? Tier::correctly_rounded
                            : worst <= 1 ? Tier::faithful
                            : worst <= 4 ? Tier::four_units
                                         : Tier::policy)
           : approximate ? Tier::approximate
                         : Tier::fail;
  if (o.pass) o.tier = std::max(o.tier, grading.best);
  return o;
}

const char* tier_name(Tier t) {
  switch (t) {
    case Tier::correctly_rounded: return "correctly-rounded";
    case Tier::faithful: return "faithful";
    case Tier::four_units: return "4u";
    case Tier::policy: return "policy";
    case Tier::approximate: return "approximate";
    case Tier::fail: return "fail";
  }
  return "?";
}

Tier parse_tier(const std::string& name) {
  for (const Tier t :
       {Tier::correctly_rounded, Tier::faithful, Tier::four_units, Tier::policy, Tier::approximate, Tier::fail})
    if (name == tier_name(t)) return t;
  throw std::invalid_argument("unknown tier '" + name +
                              "' (expected correctly-rounded, faithful, 4u, policy, approximate or fail)");
}

}  // namespace hinge::conformance
