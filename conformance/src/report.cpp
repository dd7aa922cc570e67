// The report of hinge conform, as text and as JSON (hinge/conformance/report.hpp).
#include "hinge/conformance/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

namespace hinge::conformance {
namespace {

std::string entry_name(const Grading& grading, int group, int entry) {
  std::string name = group_name(grading, group);
  if (group == 0) return name;
  name += "[";
  name += std::to_string(entry);
  return name + "]";
}

std::string fixed(double v, int digits = 1) {
  if (std::isinf(v)) return "inf";
  if (std::isnan(v)) return "-";
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

const char* unit_name(Dtype d) { return d == Dtype::float32 ? "2^-24" : "2^-53"; }

const char* status_name(CandidateResult::Status s) {
  switch (s) {
    case CandidateResult::Status::missing: return "missing";
    case CandidateResult::Status::error: return "reported an error";
    case CandidateResult::Status::nonfinite: return "non-finite";
    case CandidateResult::Status::ok: return "ok";
  }
  return "?";
}

// The consistency checks, per kind: how many, how many failed, the worst (discrepancy / threshold).
void print_checks(std::ostream& out, const std::vector<ConsistencyCheck>& checks) {
  if (checks.empty()) return;
  std::vector<std::string> kinds;
  for (const ConsistencyCheck& c : checks)
    if (std::find(kinds.begin(), kinds.end(), c.check) == kinds.end()) kinds.push_back(c.check);
  std::size_t failed = 0;
  for (const ConsistencyCheck& c : checks) failed += !c.pass;
  out << "\nconsistency checks (docs/energy-conformance.md): " << checks.size() << " checks, " << failed
      << " failed; a check fails where its discrepancy exceeds both 8 times its error estimate and the floor\n";
  for (const std::string& kind : kinds) {
    const ConsistencyCheck* worst = nullptr;
    std::size_t count = 0, failing = 0;
    const auto ratio = [](const ConsistencyCheck& c) {
      return c.threshold > 0 ? c.discrepancy / c.threshold : c.discrepancy;
    };
    for (const ConsistencyCheck& c : checks) {
      if (c.check != kind) continue;
      ++count;
      failing += !c.pass;
      if (!worst || !(ratio(c) <= ratio(*worst))) worst = &c;
    }
    out << (failing ? "FAIL " : "pass ") << kind << ": " << count << " hinges, " << failing << " failed; worst "
        << worst->case_id << ": discrepancy " << exact(worst->discrepancy) << " (threshold " << exact(worst->threshold)
        << ")";
    if (!worst->detail.empty()) out << "; " << worst->detail;
    out << '\n';
  }
}

}  // namespace

std::vector<CategorySummary> summarize(const std::vector<CaseOutcome>& outcomes) {
  std::vector<std::string> order;  // categories in the order of their first case
  for (const CaseOutcome& o : outcomes)
    if (std::find(order.begin(), order.end(), o.category) == order.end()) order.push_back(o.category);
  std::vector<CategorySummary> out;
  for (const std::string& category : order) {
    CategorySummary s;
    s.category = category;
    std::array<std::vector<double>, 3> errors;
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
      const CaseOutcome& o = outcomes[i];
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
        s.worst_index = i;
      }
    }
    for (int g = 0; g < 3; ++g) {
      auto& v = errors[g];
      if (std::isnan(v.front())) {  // a group not given
        s.median[g] = s.worst[g] = std::numeric_limits<double>::quiet_NaN();
        continue;
      }
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

std::array<double, 12> candidate_order(const std::array<double, 12>& x, const Stencil& stencil) {
  std::array<double, 12> y{};
  for (int j = 0; j < 4; ++j)
    for (int c = 0; c < 3; ++c) y[3 * j + c] = x[3 * stencil[j] + c];
  return y;
}

Report make_report(std::string candidate, std::vector<Expected> expected, std::vector<CandidateResult> results,
                   const Grading& grading, const Stencil& stencil, std::string depth) {
  if (expected.size() != results.size()) throw std::invalid_argument("make_report: one result per case");
  Report r;
  r.candidate = std::move(candidate);
  r.grading = grading;
  r.depth = std::move(depth);
  r.stencil = stencil;
  r.expected = std::move(expected);
  r.results.reserve(results.size());
  for (CandidateResult& c : results) {
    CandidateResult rounded = rounded_to(grading.dtype, std::move(c));
    if (grading.dtype == Dtype::float32 && rounded.status == CandidateResult::Status::ok) {
      bool finite = true;  // a finite value that overflows float when rounded to it
      const auto check = [&](const double* v, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) finite = finite && std::isfinite(v[i]);
      };
      if (grading.given[0]) check(&rounded.theta, 1);
      if (grading.given[1]) check(rounded.grad.data(), 12);
      if (grading.given[2]) check(rounded.hess.data(), 144);
      if (!finite) {
        rounded.status = CandidateResult::Status::nonfinite;
        rounded.error = "an output overflows float32";
      }
    }
    r.results.push_back(std::move(rounded));
  }
  for (std::size_t i = 0; i < r.expected.size(); ++i)
    r.outcomes.push_back(compare(r.expected[i], r.results[i], grading));
  r.categories = summarize(r.outcomes);
  if (!grading.energy)
    r.diagnosis = diagnose(r.expected, r.results, r.outcomes, grading, stencil);  // energies: their own
  r.passed = !r.categories.empty();
  r.tier = Tier::correctly_rounded;
  for (const CategorySummary& s : r.categories) {
    r.passed = r.passed && s.pass;
    r.tier = std::max(r.tier, s.tier);
  }
  if (r.categories.empty()) r.tier = Tier::fail;
  return r;
}

void print_report(std::ostream& out, const Report& report) {
  const Policy& policy = report.grading.policy;
  const Dtype dtype = report.grading.dtype;
  std::size_t cases = report.outcomes.size();
  out << "hinge conform: " << report.candidate << " on " << cases << " cases";
  out << " (dtype " << dtype_name(dtype) << ", depth " << report.depth;
  for (const auto& [key, value] : report.settings) out << ", " << key << " " << value;
  out << ")";
  out << "\nnormwise errors in units of " << unit_name(dtype)
      << " (median / worst); tolerance per case and output: " << fixed(policy.base, 0) << " + " << fixed(policy.c, 0)
      << " kappa (docs/conformance.md)\n";
  std::string not_checked;
  for (int g = 0; g < 3; ++g)
    if (!report.grading.given[g])
      not_checked += std::string(not_checked.empty() ? "" : ", ") + group_name(report.grading, g);
  if (!not_checked.empty()) out << "not checked (not given): " << not_checked << "\n";
  out << '\n';
  char line[512];
  int width = 18;  // the category column: the longest name
  for (const CategorySummary& s : report.categories) width = std::max(width, static_cast<int>(s.category.size()));
  std::snprintf(line, sizeof line, "%-*s %5s %7s %9s  %-19s %-19s %-19s %-6s %-17s %s\n", width, "category", "cases",
                "missing", "nonfinite", group_name(report.grading, 0), "grad", "hess", "result", "tier",
                "worst case (error / tolerance)");
  out << line;
  for (const CategorySummary& s : report.categories) {
    auto pair = [](double a, double b) {
      return std::isnan(a) ? std::string("not checked") : fixed(a) + " / " + fixed(b);
    };
    std::snprintf(line, sizeof line, "%-*s %5d %7d %9d  %-19s %-19s %-19s %-6s %-17s %s (%s)\n", width,
                  s.category.c_str(), s.cases, s.missing, s.nonfinite, pair(s.median[0], s.worst[0]).c_str(),
                  pair(s.median[1], s.worst[1]).c_str(), pair(s.median[2], s.worst[2]).c_str(),
                  s.pass ? "pass" : "FAIL", tier_name(s.tier), s.worst_id.c_str(), fixed(s.worst_ratio, 2).c_str());
    out << line;
  }
  out << '\n';
  for (const CategorySummary& s : report.categories) {
    if (s.pass) continue;
    const CaseOutcome& o = report.outcomes[s.worst_index];
    out << "FAIL " << s.category << ": " << s.failed << " of " << s.cases << " cases; worst case " << o.id << ": ";
    if (o.status != CandidateResult::Status::ok) {
      out << status_name(o.status);
      if (!report.results[s.worst_index].error.empty()) out << " (" << report.results[s.worst_index].error << ")";
      out << '\n';
      continue;
    }
    out << group_name(report.grading, o.group) << " error " << fixed(o.error[o.group]) << " > tolerance "
        << fixed(o.tolerance[o.group]) << " (kappa " << fixed(o.kappa[o.group], 2) << "); largest difference at "
        << entry_name(report.grading, o.group, o.entry) << ": expected " << exact(o.expected_value) << ", got "
        << exact(o.candidate_value) << '\n';
  }
  for (const std::string& note : report.notes) out << "note: " << note << '\n';
  print_checks(out, report.checks);
  if (!report.diagnosis.empty()) {
    out << "\ndiagnosis (" << (report.grading.energy ? "docs/energy-conformance.md" : "docs/conformance.md")
        << ", \"Diagnosis\"):\n";
    for (const Finding& f : report.diagnosis) out << "- " << f.sentence << '\n';
  }
  out << "\ntiers, best first (docs/conformance.md): correctly-rounded, faithful (<= 1 unit), 4u (<= 4 units), "
         "policy,\n"
         "approximate (outside the policy, within "
      << (dtype == Dtype::float32 ? "2^-8" : "2^-20")
      << " (1 + kappa) relative: not accurate), fail; a category's tier is the one\nits every case reaches\n";
  bool consistent = true;
  for (const ConsistencyCheck& c : report.checks) consistent = consistent && c.pass;
  if (report.passed)
    out << (report.categories.empty() ? "PASS: every consistency check passes\n"
            : report.checks.empty()   ? "PASS: every category is within the tolerance policy\n"
                                      : "PASS: every category is within the tolerance policy and every consistency "
                                        "check passes\n");
  else
    out << (consistent ? "FAIL: the candidate is outside the tolerance policy (exit status 1)\n"
                       : "FAIL: the candidate is outside the tolerance policy or fails a consistency check (exit "
                         "status 1)\n");
}

void write_json_report(std::ostream& out, const Report& report) {
  // Non-finite numbers (the error of a missing result, a group not given) are written as null: JSON has
  // no infinity.
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  auto groups = [&](const std::array<double, 3>& v) {
    return nlohmann::json{
        {group_name(report.grading, 0), number(v[0])}, {"grad", number(v[1])}, {"hess", number(v[2])}};
  };
  const Policy& policy = report.grading.policy;
  nlohmann::json j;
  j["candidate"] = report.candidate;
  j["policy"] = {{"base", policy.base}, {"c", policy.c}};
  j["units"] = std::string("normwise error in units of ") + unit_name(report.grading.dtype);
  j["dtype"] = dtype_name(report.grading.dtype);
  j["depth"] = report.depth;
  if (!report.settings.empty()) {
    j["settings"] = nlohmann::json::object();
    for (const auto& [key, value] : report.settings) j["settings"][key] = value;
  }
  j["stencil"] = nlohmann::json::array();
  for (const int v : report.stencil) j["stencil"].push_back(std::string{'x', static_cast<char>('0' + v)});
  j["given"] = nlohmann::json::array();
  for (int g = 0; g < 3; ++g)
    if (report.grading.given[g]) j["given"].push_back(group_name(report.grading, g));
  j["categories"] = nlohmann::json::array();
  for (const CategorySummary& s : report.categories) {
    const CaseOutcome& o = report.outcomes[s.worst_index];
    const Expected& e = report.expected[s.worst_index];
    nlohmann::json detail{{"id", o.id},
                          {"x", e.input.x},
                          {"x_candidate", candidate_order(e.input.x, report.stencil)},
                          {"status", status_name(o.status)}};
    if (e.input.rest) {
      detail["rest"] = *e.input.rest;
      detail["rest_candidate"] = candidate_order(*e.input.rest, report.stencil);
    }
    if (o.status == CandidateResult::Status::ok) {
      detail["output"] = group_name(report.grading, o.group);
      detail["entry"] = o.entry;
      detail["expected"] = number(o.expected_value);
      detail["got"] = number(o.candidate_value);
    } else {
      detail["output"] = nullptr;
      detail["entry"] = nullptr;
      detail["expected"] = nullptr;
      detail["got"] = nullptr;
      detail["error"] = report.results[s.worst_index].error;
    }
    j["categories"].push_back({{"category", s.category},
                               {"cases", s.cases},
                               {"missing", s.missing},
                               {"nonfinite", s.nonfinite},
                               {"failed", s.failed},
                               {"median", groups(s.median)},
                               {"worst", groups(s.worst)},
                               {"worst_case", s.worst_id},
                               {"worst_ratio", number(s.worst_ratio)},
                               {"pass", s.pass},
                               {"tier", tier_name(s.tier)},
                               {"worst_case_detail", detail}});
  }
  j["pass"] = report.passed;
  j["tier"] = tier_name(report.tier);
  j["notes"] = report.notes;
  if (!report.checks.empty()) {
    j["consistency"] = nlohmann::json::array();
    for (const ConsistencyCheck& c : report.checks)
      j["consistency"].push_back({{"check", c.check},
                                  {"id", c.case_id},
                                  {"discrepancy", number(c.discrepancy)},
                                  {"estimate", number(c.estimate)},
                                  {"threshold", number(c.threshold)},
                                  {"pass", c.pass},
                                  {"detail", c.detail}});
  }
  j["diagnosis"] = nlohmann::json::array();
  for (const Finding& f : report.diagnosis) j["diagnosis"].push_back(f.sentence);
  j["findings"] = nlohmann::json::array();
  for (const Finding& f : report.diagnosis)
    j["findings"].push_back(
        {{"key", f.key}, {"explanation", f.explanation}, {"change", f.change}, {"categories", f.categories}});
  j["cases"] = nlohmann::json::array();
  for (const CaseOutcome& o : report.outcomes)
    j["cases"].push_back({{"id", o.id},
                          {"category", o.category},
                          {"status", status_name(o.status)},
                          {"error", groups(o.error)},
                          {"tolerance", groups(o.tolerance)},
                          {"kappa", groups(o.kappa)},
                          {"pass", o.pass},
                          {"tier", tier_name(o.tier)}});
  out << j.dump(1) << '\n';
}

}  // namespace hinge::conformance
