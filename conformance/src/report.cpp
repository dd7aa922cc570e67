// The report of hinge conform, as text and as JSON (hinge/conformance/report.hpp).
#include "hinge/conformance/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>

namespace hinge::conformance {
namespace {

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
                  pair(s.median[1], s.worst[1]).c_str(), pair(s.median[2], s.worst[2]).c_str(),
                  s.pass ? "pass" : "FAIL", tier_name(s.tier), s.worst_id.c_str(), fixed(s.worst_ratio, 2).c_str());
    out << line;
    all = all && s.pass;
  }
  out << '\n';
  for (const CategorySummary& s : summary) {
    if (s.pass) continue;
    const auto it =
        std::find_if(outcomes.begin(), outcomes.end(), [&](const CaseOutcome& o) { return o.id == s.worst_id; });
    const CaseOutcome& o = *it;
    out << "FAIL " << s.category << ": " << s.failed << " of " << s.cases << " cases; worst case " << o.id << ": ";
    if (o.status != CandidateResult::Status::ok) {
      out << status_name(o.status) << '\n';
      continue;
    }
    out << group_names[o.group] << " error " << fixed(o.error[o.group]) << " > tolerance "
        << fixed(o.tolerance[o.group]) << " (kappa " << fixed(o.kappa[o.group], 2) << "); largest difference at "
        << entry_name(o.group, o.entry) << ": expected " << exact(o.expected_value) << ", got "
        << exact(o.candidate_value) << '\n';
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
    report["categories"].push_back({{"category", s.category},
                                    {"cases", s.cases},
                                    {"missing", s.missing},
                                    {"nonfinite", s.nonfinite},
                                    {"failed", s.failed},
                                    {"median", groups(s.median)},
                                    {"worst", groups(s.worst)},
                                    {"worst_case", s.worst_id},
                                    {"worst_ratio", number(s.worst_ratio)},
                                    {"pass", s.pass},
                                    {"tier", tier_name(s.tier)}});
  }
  report["pass"] = all;
  report["cases"] = nlohmann::json::array();
  for (const CaseOutcome& o : outcomes)
    report["cases"].push_back({{"id", o.id},
                               {"category", o.category},
                               {"status", status_name(o.status)},
                               {"error", groups(o.error)},
                               {"tolerance", groups(o.tolerance)},
                               {"kappa", groups(o.kappa)},
                               {"pass", o.pass},
                               {"tier", tier_name(o.tier)}});
  out << report.dump(1) << '\n';
}

}  // namespace hinge::conformance
