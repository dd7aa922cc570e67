// study.md and the summary table (hinge/study/study.hpp); study.json is hinge::io's (hinge/io/study_json.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include "hinge/study/measure.hpp"
#include "study_internal.hpp"

namespace hinge::study {

namespace {

constexpr const char* groups[3] = {"theta", "grad", "hess"};

std::string label(const Row& r) { return io::row_label(r); }

// The ratio to fast in double, measured side by side (timing.hpp), or "-".
std::string ratio(const Row& r) {
  if (r.x_fast[2] <= 0) return "-";
  char b[64];
  std::snprintf(b, sizeof b, r.x_fast[2] < 10 ? "%.2f" : r.x_fast[2] < 100 ? "%.1f" : "%.0f", r.x_fast[2]);
  return b;
}

std::string fixed(double v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

// A time in ns with 3 significant digits.
std::string ns(double v) {
  if (v <= 0) return "-";
  char b[64];
  std::snprintf(b, sizeof b, v < 10 ? "%.2f" : v < 100 ? "%.1f" : "%.0f", v);
  return b;
}

// An error in units with 2 significant digits (or "0").
std::string units(double v) {
  if (v == 0) return "0";
  char b[64];
  std::snprintf(b, sizeof b, v >= 1e4 ? "%.1e" : v >= 10 ? "%.0f" : "%.2g", v);
  return b;
}

}  // namespace

void write_markdown(std::ostream& out, const Study& s) {
  out << "# hinge study\n\n";
  out << "Machine: " << s.cpu << ", clock " << fixed(s.clock_ghz, 2) << " GHz (measured). Inputs: " << s.source << ", "
      << s.hinges << " hinges certified" << (s.skipped ? " (" + std::to_string(s.skipped) + " skipped)" : "") << " in "
      << s.categories.size() << " categories. " << (s.quick ? "Quick study" : "Full study") << ", "
      << fixed(s.seconds, 0) << " s.\n\n";
  out << "## Time and accuracy per hinge\n\n";
  out << "Time: ns per hinge (one thread, the median of the row's passes), theta / theta and gradient / all\n"
         "three, and the last as a multiple of fast in double (the median of per-round ratios, the row and fast\n"
         "timed back to back: study.json's \"timing\"). Outside rows are marked (outside). Error: normwise, in units "
         "of 2^-53, each output rounded to double,\n"
         "against the certified oracle: the worst of any output (theta, gradient, Hessian) over all categories,\n"
         "and the worst Hessian error; own: the worst Hessian error in units of the type's own unit roundoff. On\n"
         "the frontier: no other row is both faster and more accurate (worst of any output).\n\n";
  out << "| method | scalar | theta ns | +grad ns | +hess ns | x fast | worst (u) | worst hess (u) | worst own hess "
         "(u_type) | failed | nonfinite | frontier |\n";
  out << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|:-:|\n";
  for (const Row& r : s.rows) {
    double own = 0;
    for (const auto& [c, e] : r.error_own) own = std::max(own, e[2].max);
    out << "| " << r.method << (r.outside ? " (outside)" : "") << " | " << r.scalar.name() << " | "
        << ns(r.ns_per_hinge[0]) << " | " << ns(r.ns_per_hinge[1]) << " | " << ns(r.ns_per_hinge[2]) << " | "
        << ratio(r) << " | " << units(r.worst) << " | " << units(r.worst_hess) << " | "
        << (r.error_own.empty() ? "-" : units(own)) << " | " << r.failed << " | " << r.nonfinite << " | "
        << (r.on_frontier ? "yes" : "") << " |\n";
  }
  for (int g = 2; g >= 0; g -= 2) {
    out << "\n## Worst " << groups[g] << " error per category (units of 2^-53, rounded to double)\n\n| method/scalar |";
    for (const auto& c : s.categories) out << " " << c << " |";
    out << "\n|---|";
    for (std::size_t i = 0; i < s.categories.size(); ++i) out << "---:|";
    out << "\n";
    for (const Row& r : s.rows) {
      out << "| " << label(r) << " |";
      for (const auto& c : s.categories) {
        const auto it = r.error_u.find(c);
        out << " " << (it == r.error_u.end() ? "-" : units(it->second[g].max)) << " |";
      }
      out << "\n";
    }
  }
  for (const Row& r : s.rows)
    if (!r.escalation.empty()) {
      out << "\n## " << label(r) << ": hinges its fast path left to the exact stage and enclosures, per category\n\n";
      out << "| category | escalated |\n|---|---:|\n";
      for (const auto& [c, f] : r.escalation) out << "| " << c << " | " << fixed(100 * f, 1) << "% |\n";
    }
  for (const Row& r : s.rows)
    if (!r.error.empty()) out << "\n" << label(r) << ": " << r.error << "\n";
  if (!s.mesh.empty()) {
    out << "\n## Mesh level: ns per interior edge (energy, gradient and Hessian of the tan energy; one thread)\n\n";
    std::vector<double> sizes;
    for (const MeshRow& m : s.mesh)
      for (double v : m.vertices)
        if (std::find(sizes.begin(), sizes.end(), v) == sizes.end()) sizes.push_back(v);
    std::sort(sizes.begin(), sizes.end());
    out << "| method | scalar |";
    for (double v : sizes) out << " " << static_cast<int>(std::lround(std::sqrt(v))) << "^2 |";
    out << " k | ln a |\n|---|---|";
    for (std::size_t i = 0; i < sizes.size() + 2; ++i) out << "---:|";
    out << "\n";
    for (const MeshRow& m : s.mesh) {
      out << "| " << methods::method_name(m.method) << " | " << m.scalar.name() << " |";
      for (double v : sizes) {
        const auto it = std::find(m.vertices.begin(), m.vertices.end(), v);
        out << " " << (it == m.vertices.end() ? "-" : ns(m.ns_per_edge[it - m.vertices.begin()])) << " |";
      }
      out << " " << (m.vertices.size() >= 2 ? fixed(m.k, 3) : "-") << " | "
          << (m.vertices.size() >= 2 ? fixed(m.ln_a, 2) : "-") << " |\n";
    }
    out << "\nk and ln a: seconds per evaluation = a n^k over the sizes measured (n vertices), fitted in log-log as "
           "in\n"
           "the paper's Table 2.\n";
    if (const SharedFit& f = s.shared_fit; !f.ln_a.empty()) {
      out << "\nAs the paper's Table 2 (double, sizes 11^2 .. 81^2): one k for all methods, the mean of theirs, k = "
          << fixed(f.k, 3) << "; ln a refitted with it, and the speedup of fast, exp(ln a_M - ln a_fast):\n\n"
          << "| method | ln a | fast's speedup |\n|---|---:|---:|\n";
      for (const auto& [method, ln_a] : f.ln_a)
        out << "| " << method << " | " << fixed(ln_a, 3) << " | "
            << (f.has_fast ? fixed(std::exp(ln_a - f.fast_ln_a), 2) : "-") << " |\n";
    }
  }
  out << "\n## Build\n\n";
  for (const auto& [k, v] : s.build) out << "- " << k << ": " << v << "\n";
}

void print_summary(std::ostream& out, const Study& s) {
  char line[256];
  std::snprintf(line, sizeof line, "hinge study: %zu hinges in %zu categories, %zu rows, %.2f GHz, %.0f s%s\n",
                s.hinges, s.categories.size(), s.rows.size(), s.clock_ghz, s.seconds, s.quick ? " (quick)" : "");
  out << line;
  std::snprintf(line, sizeof line, "%-22s %10s %8s %12s %14s %14s %8s  %s\n", "method/scalar", "hess ns", "x fast",
                "worst (u)", "worst hess (u)", "median w-s (u)", "failed", "frontier");
  out << line;
  for (const Row& r : s.rows) {
    const auto ws = r.error_u.find("well-shaped");
    const double median = ws == r.error_u.end() ? 0 : ws->second[2].median;
    std::snprintf(line, sizeof line, "%-22s %10s %8s %12s %14s %14s %8zu  %s\n",
                  (label(r) + (r.outside ? " (outside)" : "")).c_str(), ns(r.ns_per_hinge[2]).c_str(), ratio(r).c_str(),
                  units(r.worst).c_str(), units(r.worst_hess).c_str(),
                  ws == r.error_u.end() ? "-" : units(median).c_str(), r.failed + r.nonfinite,
                  r.on_frontier ? "*" : "");
    out << line;
  }
  for (const MeshRow& m : s.mesh) {
    if (m.vertices.empty()) continue;
    std::snprintf(line, sizeof line, "mesh %-9s %-12s %s ns per interior edge at %d^2",
                  std::string(methods::method_name(m.method)).c_str(), m.scalar.name().c_str(),
                  ns(m.ns_per_edge.back()).c_str(), static_cast<int>(std::lround(std::sqrt(m.vertices.back()))));
    out << line;
    if (m.vertices.size() >= 2) out << ", k = " << fixed(m.k, 3);
    out << "\n";
  }
  out << "(u: units of 2^-53, normwise, each output rounded to double, against the certified oracle; * on the "
         "frontier)\n";
}

}  // namespace hinge::study
