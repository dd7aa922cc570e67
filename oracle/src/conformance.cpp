// Certified expectations, conditioning, comparison and report of the conformance kit
// (hinge/oracle/conformance.hpp). Compiled with -ffp-contract=off: the condition numbers are part of the
// committed vectors and must come out bit for bit everywhere.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <span>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "hinge/oracle/conformance.hpp"
#include "hinge_intervals.hpp"
#include "interval.hpp"

namespace hinge::oracle::conformance {
namespace {

using detail::Interval;
using detail::Real;
constexpr double u = 0x1p-53;
constexpr double infinity = std::numeric_limits<double>::infinity();

// The largest magnitude, NaN when a value is NaN.
template <class Values>
double largest_magnitude(const Values& values) {
  double largest = 0;
  for (const double v : values)
    if (!(std::fabs(v) <= largest)) largest = std::isnan(v) ? v : std::fabs(v);
  return largest;
}

// ||v||_2 without overflow or underflow: scaled by the largest magnitude (fixed order of operations); NaN
// when an entry is.
double norm(const double* v, std::size_t n) {
  double largest = 0;
  for (std::size_t i = 0; i < n && !std::isnan(largest); ++i)
    if (!(std::fabs(v[i]) <= largest)) largest = std::isnan(v[i]) ? v[i] : std::fabs(v[i]);
  if (largest == 0 || !std::isfinite(largest)) return largest;
  double sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = v[i] / largest;
    sum += s * s;
  }
  return largest * std::sqrt(sum);
}

// The longest of the five edge vectors, exactly squared in integer units, then rounded: L.
double longest_edge(const ScaledHinge& s, Int& longest_squared) {
  static constexpr int ends[5][2] = {{2, 1}, {0, 2}, {1, 0}, {3, 2}, {1, 3}};
  longest_squared = 0;
  for (const auto& e : ends) {
    Int d = 0;
    for (int c = 0; c < 3; ++c) {
      const Int t = s.X[3 * e[0] + c] - s.X[3 * e[1] + c];
      d += t * t;
    }
    if (d > longest_squared) longest_squared = d;
  }
  Real L(128);
  mpfr_set_z(L.get(), longest_squared.get_mpz_t(), MPFR_RNDN);
  mpfr_sqrt(L.get(), L.get(), MPFR_RNDN);
  mpfr_mul_2si(L.get(), L.get(), -s.F, MPFR_RNDN);
  return mpfr_get_d(L.get(), MPFR_RNDN);
}

// L ||d Hess theta / dx||_F: central differences of the exact Hessian, step one unit of the refined
// integers (at most 2^-100 L), evaluated at 320 bits. The truncation error is relatively
// O((step / h_min)^2), far below what a condition number needs.
double third_derivative_scale(const ScaledHinge& s, const Int& longest_squared, double L) {
  const std::size_t length_bits = (mpz_sizeinbase(longest_squared.get_mpz_t(), 2) + 1) / 2;
  const unsigned long extra = length_bits >= 100 ? 0 : 100 - length_bits;
  const ScaledHinge refined = refine(s, extra);
  detail::WorkingPrecision precision(320);
  Real sum(320), term(320);
  mpfr_set_ui(sum.get(), 0, MPFR_RNDN);
  for (int j = 0; j < 12; ++j) {
    ScaledHinge plus = refined, minus = refined;
    plus.X[j] += 1;
    minus.X[j] -= 1;
    const ExactHinge ep = exact_hinge(plus, true), em = exact_hinge(minus, true);
    const Interval lp = sqrt(Interval(ep.s)), lm = sqrt(Interval(em.s));
    for (int k = 0; k < 144; ++k) {
      const Interval d = detail::quotient(ep.h[k], ep.h_den, lp, 2 * ep.F) - detail::quotient(em.h[k], em.h_den, lm, 2 * em.F);
      mpfi_mid(term.get(), d.get());
      mpfr_mul_2si(term.get(), term.get(), refined.F - 1, MPFR_RNDN);  // / (2 step), step = 2^-F
      mpfr_sqr(term.get(), term.get(), MPFR_RNDN);
      mpfr_add(sum.get(), sum.get(), term.get(), MPFR_RNDN);
    }
  }
  mpfr_sqrt(sum.get(), sum.get(), MPFR_RNDN);
  mpfr_mul_d(sum.get(), sum.get(), L, MPFR_RNDN);
  return mpfr_get_d(sum.get(), MPFR_RNDN);
}

const double* group_data(const CertifiedTheta& v, int g) { return g == 0 ? &v.theta : g == 1 ? v.grad.data() : v.hess.data(); }
const double* group_data(const CandidateResult& v, int g) { return g == 0 ? &v.theta : g == 1 ? v.grad.data() : v.hess.data(); }
constexpr std::size_t group_size[3] = {1, 12, 144};

std::string entry_name(int group, int entry) {
  if (group == 0) return "theta";
  return std::string(group_names[group]) + "[" + std::to_string(entry) + "]";
}

std::string fixed(double v, int digits = 1) {
  if (std::isinf(v)) return "inf";
  char buffer[64];
  if (v >= 1e7) std::snprintf(buffer, sizeof buffer, "%.3g", v);
  else std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

std::string exact(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

const char* status_name(CandidateResult::Status s) {
  switch (s) {
    case CandidateResult::Status::missing: return "missing";
    case CandidateResult::Status::error: return "reported an error";
    case CandidateResult::Status::nonfinite: return "non-finite";
    case CandidateResult::Status::ok: return "ok";
  }
  return "?";
}

}  // namespace

Expected expected(const Case& c) {
  Expected e;
  e.input = c;
  const ScaledHinge s = scale_exactly(c.x);
  e.values = certify(exact_hinge(s, true));
  Int longest_squared;
  Conditioning& k = e.conditioning;
  k.length = longest_edge(s, longest_squared);
  k.scale[0] = k.length * norm(e.values.grad.data(), 12);  // J_theta = grad theta
  k.scale[1] = k.length * norm(e.values.hess.data(), 144);  // J_grad = Hess theta
  k.scale[2] = third_derivative_scale(s, longest_squared, k.length);
  for (int g = 0; g < 3; ++g) {
    const double size = norm(group_data(e.values, g), group_size[g]);
    k.kappa[g] = size == 0 ? 1.0 : k.scale[g] / size;
  }
  return e;
}

double normwise_error(const double* candidate, const double* certified, std::size_t n, double scale_if_zero) {
  std::array<double, 144> difference{};
  if (n > difference.size()) throw std::invalid_argument("normwise_error: at most 144 values");
  for (std::size_t i = 0; i < n; ++i) difference[i] = candidate[i] - certified[i];
  const double size = norm(certified, n);
  const double normalizer = size > 0 ? size : scale_if_zero;
  const double d = norm(difference.data(), n);
  return d == 0 ? 0.0 : normalizer > 0 && std::isfinite(d) ? d / normalizer / u : infinity;
}

double symmetric_frobenius(const Eigen::SparseMatrix<double>& upper) {
  const double largest = largest_magnitude(std::span<const double>(upper.valuePtr(), static_cast<std::size_t>(upper.nonZeros())));
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
  const double size = norm(m.rounded.gradient.data(), m.rounded.gradient.size());
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
  const double size = norm(want.data(), want.size());
  MeshComparison c;
  c.kappa_sum = gradient_kappa_sum(m);
  c.error = norm(difference.data(), difference.size()) / (size > 0 ? size : 1) / u;
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
      if (std::fabs(difference[i]) > std::fabs(difference[largest]) || std::isnan(difference[i])) largest = static_cast<int>(i);
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
  o.tier = !o.pass ? Tier::fail
           : equal ? Tier::correctly_rounded
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

std::vector<CategorySummary> summarize(const std::vector<CaseOutcome>& outcomes) {
  std::vector<CategorySummary> out;
  for (const std::string& category : categories()) {
    CategorySummary s;
    s.category = category;
    std::array<std::vector<double>, 3> errors;
    for (const CaseOutcome& o : outcomes) {
      if (o.category != category) continue;
      ++s.cases;
      if (o.status == CandidateResult::Status::missing || o.status == CandidateResult::Status::error) ++s.missing;
      if (o.status == CandidateResult::Status::nonfinite) ++s.nonfinite;
      if (!o.pass) ++s.failed;
      s.tier = std::max(s.tier, o.tier);
      for (int g = 0; g < 3; ++g) errors[g].push_back(o.error[g]);
      if (s.worst_id.empty() || o.ratio > s.worst_ratio) {
        s.worst_ratio = o.ratio;
        s.worst_id = o.id;
      }
    }
    if (s.cases == 0) continue;
    for (int g = 0; g < 3; ++g) {
      auto& v = errors[g];
      std::sort(v.begin(), v.end());
      const std::size_t n = v.size();
      s.median[g] = n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
      s.worst[g] = v.back();
    }
    s.pass = s.failed == 0;
    out.push_back(s);
  }
  return out;
}

bool print_report(std::ostream& out, const std::vector<CaseOutcome>& outcomes, const Policy& policy,
                  const std::string& candidate) {
  const std::vector<CategorySummary> summary = summarize(outcomes);
  out << "hinge conform: " << candidate << " on " << outcomes.size() << " cases\n"
      << "normwise errors in units of 2^-53 (median / worst); tolerance per case and output: " << fixed(policy.base, 0)
      << " + " << fixed(policy.c, 0) << " kappa (docs/conformance.md)\n\n";
  char line[512];
  std::snprintf(line, sizeof line, "%-18s %5s %7s %9s  %-19s %-19s %-19s %-6s %-17s %s\n", "category", "cases",
                "missing", "nonfinite", "theta", "grad", "hess", "result", "tier", "worst case (error / tolerance)");
  out << line;
  bool all = true;
  for (const CategorySummary& s : summary) {
    auto pair = [](double a, double b) { return fixed(a) + " / " + fixed(b); };
    std::snprintf(line, sizeof line, "%-18s %5d %7d %9d  %-19s %-19s %-19s %-6s %-17s %s (%s)\n", s.category.c_str(),
                  s.cases, s.missing, s.nonfinite, pair(s.median[0], s.worst[0]).c_str(),
                  pair(s.median[1], s.worst[1]).c_str(), pair(s.median[2], s.worst[2]).c_str(), s.pass ? "pass" : "FAIL",
                  tier_name(s.tier), s.worst_id.c_str(), fixed(s.worst_ratio, 2).c_str());
    out << line;
    all = all && s.pass;
  }
  out << '\n';
  for (const CategorySummary& s : summary) {
    if (s.pass) continue;
    const auto it = std::find_if(outcomes.begin(), outcomes.end(), [&](const CaseOutcome& o) { return o.id == s.worst_id; });
    const CaseOutcome& o = *it;
    out << "FAIL " << s.category << ": " << s.failed << " of " << s.cases << " cases; worst case " << o.id << ": ";
    if (o.status != CandidateResult::Status::ok) {
      out << status_name(o.status) << '\n';
      continue;
    }
    out << group_names[o.group] << " error " << fixed(o.error[o.group]) << " > tolerance " << fixed(o.tolerance[o.group])
        << " (kappa " << fixed(o.kappa[o.group], 2) << "); largest difference at " << entry_name(o.group, o.entry)
        << ": expected " << exact(o.expected_value) << ", got " << exact(o.candidate_value) << '\n';
  }
  out << "tiers (docs/conformance.md): correctly-rounded, faithful (<= 1 unit), 4u (<= 4 units), policy, fail: the\n"
         "tier each category's every case reaches\n";
  out << (all ? "PASS: every category is within the tolerance policy\n"
              : "FAIL: the candidate is outside the tolerance policy (exit status 1)\n");
  return all;
}

void write_json_report(std::ostream& out, const std::vector<CaseOutcome>& outcomes, const Policy& policy,
                       const std::string& candidate) {
  // Non-finite numbers (the error of a missing result) are written as null: JSON has no infinity.
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  auto groups = [&](const std::array<double, 3>& v) {
    return nlohmann::json{{"theta", number(v[0])}, {"grad", number(v[1])}, {"hess", number(v[2])}};
  };
  const std::vector<CategorySummary> summary = summarize(outcomes);
  nlohmann::json report;
  report["candidate"] = candidate;
  report["policy"] = {{"base", policy.base}, {"c", policy.c}};
  report["units"] = "normwise error in units of 2^-53";
  bool all = true;
  report["categories"] = nlohmann::json::array();
  for (const CategorySummary& s : summary) {
    all = all && s.pass;
    report["categories"].push_back({{"category", s.category}, {"cases", s.cases}, {"missing", s.missing},
                                    {"nonfinite", s.nonfinite}, {"failed", s.failed}, {"median", groups(s.median)},
                                    {"worst", groups(s.worst)}, {"worst_case", s.worst_id},
                                    {"worst_ratio", number(s.worst_ratio)}, {"pass", s.pass}, {"tier", tier_name(s.tier)}});
  }
  report["pass"] = all;
  report["cases"] = nlohmann::json::array();
  for (const CaseOutcome& o : outcomes)
    report["cases"].push_back({{"id", o.id}, {"category", o.category}, {"status", status_name(o.status)},
                               {"error", groups(o.error)}, {"tolerance", groups(o.tolerance)}, {"kappa", groups(o.kappa)},
                               {"pass", o.pass}, {"tier", tier_name(o.tier)}});
  out << report.dump(1) << '\n';
}

}  // namespace hinge::oracle::conformance
