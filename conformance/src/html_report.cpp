// The report of a conformance run as one self-contained HTML page (hinge/conformance/html_report.hpp): inline
// CSS and SVG only, no script, every link a `#` fragment.
#include "hinge/conformance/html_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace hinge::conformance {
namespace {

using Status = CandidateResult::Status;

// Text for the page. Beside the markup characters, `(`, `)`, `=` and `@` become character references, so
// that no text (a candidate's name, an error message) can read as `src=`, `url(` or `@import` to a checker
// of the page's self-containment.
std::string escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      case '(': out += "&#40;"; break;
      case ')': out += "&#41;"; break;
      case '=': out += "&#61;"; break;
      case '@': out += "&#64;"; break;
      default: out += ch;
    }
  }
  return out;
}

// A number as the report shows it: 3 significant digits, "inf" for an infinity, "n/a" for a NaN.
std::string num(double v) {
  if (std::isnan(v)) return "n/a";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

// A double exactly (17 significant digits; "inf", "n/a" where it is not finite).
std::string exact(double v) {
  if (std::isnan(v)) return "n/a";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// A double as a Python literal (float("inf"), float("nan") where it is not finite).
std::string python(double v) {
  if (std::isnan(v)) return "float(\"nan\")";
  if (std::isinf(v)) return v > 0 ? "float(\"inf\")" : "-float(\"inf\")";
  return exact(v);
}

// An SVG coordinate.
std::string px(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v);
  return buffer;
}

const char* status_name(Status s) {
  switch (s) {
    case Status::missing: return "missing";
    case Status::error: return "reported an error";
    case Status::nonfinite: return "non-finite";
    case Status::ok: return "ok";
  }
  return "?";
}

// The CSS class of a tier's colour.
const char* tier_class(Tier t) {
  switch (t) {
    case Tier::correctly_rounded: return "t-cr";
    case Tier::faithful: return "t-fa";
    case Tier::four_units: return "t-4u";
    case Tier::policy: return "t-po";
    case Tier::approximate: return "t-ap";
    case Tier::fail: return "t-fail";
  }
  return "t-fail";
}

// "x2.y": the contract's label of variable i (vertex-major).
std::string variable(int i) { return {'x', static_cast<char>('0' + i / 3), '.', "xyz"[i % 3]}; }

// The candidate's variable index holding the contract's variable i: its vertex j is the contract's
// x_{stencil[j]}.
int candidate_variable(const Stencil& stencil, int i) {
  for (int j = 0; j < 4; ++j)
    if (stencil[j] == i / 3) return 3 * j + i % 3;
  return i;
}

// The contract's variable held by the candidate's variable a.
int contract_variable(const Stencil& stencil, int a) { return 3 * stencil[a / 3] + a % 3; }

const double* group_values(const CertifiedTheta& v, int g) {
  return g == 0 ? &v.theta : g == 1 ? v.grad.data() : v.hess.data();
}
const double* group_values(const CandidateResult& v, int g) {
  return g == 0 ? &v.theta : g == 1 ? v.grad.data() : v.hess.data();
}
constexpr std::array<std::size_t, 3> group_sizes{1, 12, 144};

// "2^-53" or "2^-24": the unit of every error.
const char* unit_text(Dtype d) { return d == Dtype::float32 ? "2<sup>-24</sup>" : "2<sup>-53</sup>"; }
// The relative error of the tier `approximate`.
const char* approximate_text(Dtype d) { return d == Dtype::float32 ? "2<sup>-8</sup>" : "2<sup>-20</sup>"; }

constexpr const char* style = R"(
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",Helvetica,Arial,sans-serif;color:#1d2125;margin:0;background:#f6f7f9}
main{max-width:1180px;margin:0 auto;padding:16px 24px 48px}
h1{font-size:22px;margin:8px 0 4px}h2{font-size:18px;margin:28px 0 8px;border-bottom:1px solid #d0d5db;padding-bottom:4px}
h3{font-size:15px;margin:18px 0 6px}
nav a{margin-right:14px;color:#2c5fa8;text-decoration:none}
.verdict{display:inline-block;font-weight:700;padding:2px 10px;border-radius:4px;color:#fff}
.verdict.pass{background:#1f7a3a}.verdict.fail{background:#b3261e}
dl.meta{display:grid;grid-template-columns:max-content auto;gap:2px 14px;margin:10px 0}
dl.meta dt{color:#5b636b}dl.meta dd{margin:0}
.diagnosis{background:#fff4e5;border:2px solid #e08a00;border-radius:6px;padding:10px 16px;margin:16px 0}
.diagnosis h2{border:none;margin:0 0 6px;font-size:17px}.diagnosis li{margin:4px 0;font-size:15px}
table{border-collapse:collapse;background:#fff;margin:6px 0}
th,td{border:1px solid #d0d5db;padding:3px 7px;text-align:right;white-space:nowrap}
th{background:#eceff3;font-weight:600}td.l,th.l{text-align:left}
.t-cr{background:#1b7837;color:#fff}.t-fa{background:#5aae61;color:#fff}.t-4u{background:#a6dba0}
.t-po{background:#e6f0b8}.t-ap{background:#fdb863}.t-fail{background:#d7301f;color:#fff}
.nc{background:#e3e5e8;color:#5b636b;font-style:italic}
.card{background:#fff;border:1px solid #d0d5db;border-radius:6px;padding:10px 14px;margin:10px 0}
svg{max-width:100%;height:auto}svg text{font:11px system-ui,Helvetica,Arial,sans-serif;fill:#1d2125}
svg .grid{stroke:#e6e8eb}svg .axis{stroke:#5b636b;fill:none}svg .band{stroke:#b8bec5;stroke-dasharray:3 3}
svg .tol{stroke:#1d2125;stroke-width:1.6;fill:none}svg .apx{stroke:#e08a00;stroke-width:1.6;stroke-dasharray:6 4;fill:none}
svg circle.p{fill:#2c7bb6;fill-opacity:.7}svg circle.a{fill:#e08a00;fill-opacity:.85}svg circle.f{fill:#d7301f;fill-opacity:.85}
svg circle.m{fill:#fff;stroke:#d7301f;stroke-width:1.2}
.key{display:inline-block;width:10px;height:10px;border-radius:50%;margin:0 4px 0 12px;vertical-align:-1px}
.key.p{background:#2c7bb6}.key.a{background:#e08a00}.key.f{background:#d7301f}.key.m{border:1.5px solid #d7301f}
.line{display:inline-block;width:22px;height:0;border-top:2px solid #1d2125;margin:0 4px 3px 12px}
.line.apx{border-top:2px dashed #e08a00}
pre{background:#fbfbfc;border:1px solid #d0d5db;border-radius:4px;padding:8px 10px;overflow-x:auto;font-size:12px}
.note{color:#5b636b}
)";

// The case reproduced and mapped: the failing case with outputs and the largest ratio; when no failing case
// has outputs, the first failing one (then `with_outputs` is false). None when every case passes.
struct Chosen {
  std::size_t index = 0;
  bool found = false, with_outputs = false;
};

Chosen choose_worst_failing(const Report& report) {
  Chosen chosen;
  for (std::size_t i = 0; i < report.outcomes.size(); ++i) {
    const CaseOutcome& o = report.outcomes[i];
    if (o.pass) continue;
    if (o.status == Status::ok) {
      if (!chosen.with_outputs || o.ratio > report.outcomes[chosen.index].ratio) chosen = {i, true, true};
    } else if (!chosen.found) {
      chosen = {i, true, false};
    }
  }
  return chosen;
}

void header(std::ostream& out, const Report& r) {
  const Grading& gr = r.grading;
  out << "<header><h1><span class=\"verdict " << (r.passed ? "pass\">PASS" : "fail\">FAIL") << "</span> "
      << escape(r.candidate) << "</h1>\n<dl class=\"meta\">\n";
  out << "<dt>result</dt><dd>"
      << (r.passed ? "passed: every category is within the tolerance policy"
                   : "not passed: some category is outside the tolerance policy")
      << "</dd>\n";
  out << "<dt>overall tier</dt><dd><span class=\"" << tier_class(r.tier) << "\">&nbsp;" << tier_name(r.tier)
      << "&nbsp;</span> (the lowest category tier)</dd>\n";
  out << "<dt>dtype</dt><dd>" << dtype_name(gr.dtype) << ": every error in units of u = " << unit_text(gr.dtype)
      << "</dd>\n";
  out << "<dt>depth</dt><dd>" << escape(r.depth) << ", " << r.outcomes.size() << " cases in " << r.categories.size()
      << " categories</dd>\n";
  out << "<dt>outputs checked</dt><dd>";
  std::string given;
  for (int g = 0; g < 3; ++g)
    if (gr.given[g]) given += (given.empty() ? "" : ", ") + std::string(group_name(r.grading, g));
  out << (given.empty() ? "none" : given);
  for (int g = 0; g < 3; ++g)
    if (!gr.given[g]) out << "; " << group_name(r.grading, g) << " not checked";
  out << "</dd>\n";
  out << "<dt>stencil</dt><dd>" << escape(stencil_name(r.stencil))
      << (r.stencil == contract_stencil ? " (the contract's order)"
                                        : ": your vertex j is the contract's x<sub>stencil[j]</sub>")
      << "</dd>\n";
  out << "<dt>tolerance policy</dt><dd>an output group passes when its normwise error ||got &minus; expected|| / "
         "(u ||expected||) is at most "
      << num(gr.policy.base) << " + " << num(gr.policy.c)
      << " &kappa; (&kappa; its condition number; relative to its scale where the expected output is zero)</dd>\n";
  out << "<dt>approximate</dt><dd>outside the policy but within " << approximate_text(gr.dtype)
      << " (1 + &kappa;) relative, i.e. " << num(approximate_bound(gr.dtype))
      << " (1 + &kappa;) units of u: the formula looks right and is not accurate (not passed)</dd>\n";
  out << "<dt>tiers</dt><dd>";
  for (const Tier t :
       {Tier::correctly_rounded, Tier::faithful, Tier::four_units, Tier::policy, Tier::approximate, Tier::fail})
    out << "<span class=\"" << tier_class(t) << "\">&nbsp;" << tier_name(t) << "&nbsp;</span> ";
  out << " best first: every output exact; within 1 unit; within 4 units; within the policy; within the "
         "approximate bound; outside it</dd>\n</dl></header>\n";
}

void diagnosis(std::ostream& out, const Report& r) {
  if (!r.notes.empty()) {
    out << "<ul class=\"notes\">\n";
    for (const std::string& note : r.notes) out << "<li>" << escape(note) << "</li>\n";
    out << "</ul>\n";
  }
  if (r.diagnosis.empty()) return;
  out << "<section class=\"diagnosis\" id=\"diagnosis\"><h2>Diagnosis</h2><ul>\n";
  for (const Finding& f : r.diagnosis) out << "<li>" << escape(f.sentence) << "</li>\n";
  out << "</ul></section>\n";
}

void category_table(std::ostream& out, const Report& r) {
  const Grading& gr = r.grading;
  out << "<section id=\"categories\"><h2>Tiers per category</h2>\n<table>\n<tr><th class=\"l\" rowspan=\"2\">"
         "category</th><th rowspan=\"2\">cases</th><th rowspan=\"2\">missing</th><th rowspan=\"2\">non-finite</th>"
         "<th rowspan=\"2\">failed</th>";
  for (int g = 0; g < 3; ++g) out << "<th colspan=\"2\">" << group_name(r.grading, g) << "</th>";
  out << "<th rowspan=\"2\">tier</th><th class=\"l\" rowspan=\"2\">worst case (error / tolerance)</th></tr>\n<tr>";
  for (int g = 0; g < 3; ++g) out << "<th>median</th><th>worst</th>";
  out << "</tr>\n";
  for (const CategorySummary& s : r.categories) {
    out << "<tr><td class=\"l\">" << escape(s.category) << "</td><td>" << s.cases << "</td><td>" << s.missing
        << "</td><td>" << s.nonfinite << "</td><td>" << s.failed << "</td>";
    for (int g = 0; g < 3; ++g) {
      if (!gr.given[g]) out << "<td class=\"nc\" colspan=\"2\">not checked</td>";
      else out << "<td>" << num(s.median[g]) << "</td><td>" << num(s.worst[g]) << "</td>";
    }
    out << "<td class=\"" << tier_class(s.tier) << "\">" << tier_name(s.tier) << "</td><td class=\"l\">"
        << escape(s.worst_id) << " (" << num(s.worst_ratio) << ")</td></tr>\n";
  }
  out << "</table>\n<p class=\"note\">Errors in units of u, normwise per output group; a missing or non-finite "
         "result has error inf and counts in the median and the worst.</p>\n";

  // The worst failing cases, at most ten.
  std::vector<std::size_t> failing;
  for (std::size_t i = 0; i < r.outcomes.size(); ++i)
    if (!r.outcomes[i].pass) failing.push_back(i);
  std::stable_sort(failing.begin(), failing.end(), [&](std::size_t a, std::size_t b) {
    const double ra = r.outcomes[a].ratio, rb = r.outcomes[b].ratio;
    return (std::isnan(rb) && !std::isnan(ra)) || ra > rb;
  });
  if (!failing.empty()) {
    out << "<h3>Worst failing cases (" << std::min<std::size_t>(failing.size(), 10) << " of " << failing.size()
        << ")</h3>\n<table><tr><th class=\"l\">case</th><th class=\"l\">status</th><th>group</th><th>error</th>"
           "<th>tolerance</th><th>&kappa;</th><th>error / tolerance</th><th>tier</th></tr>\n";
    for (std::size_t k = 0; k < failing.size() && k < 10; ++k) {
      const CaseOutcome& o = r.outcomes[failing[k]];
      const bool ok = o.status == Status::ok;
      out << "<tr><td class=\"l\">" << escape(o.id) << "</td><td class=\"l\">" << status_name(o.status);
      if (!ok && failing[k] < r.results.size() && !r.results[failing[k]].error.empty())
        out << ": " << escape(r.results[failing[k]].error);
      out << "</td>";
      if (ok)
        out << "<td>" << group_name(r.grading, o.group) << "</td><td>" << num(o.error[o.group]) << "</td><td>"
            << num(o.tolerance[o.group]) << "</td><td>" << num(o.kappa[o.group]) << "</td>";
      else out << "<td></td><td>inf</td><td></td><td></td>";
      out << "<td>" << num(o.ratio) << "</td><td class=\"" << tier_class(o.tier) << "\">" << tier_name(o.tier)
          << "</td></tr>\n";
    }
    out << "</table>\n";
  }
  out << "</section>\n";
}

// Labels "10^k" of the decades lo..hi, at most about ten of them.
int label_step(int lo, int hi) { return std::max(1, (hi - lo + 9) / 10); }

void power_of_ten(std::ostream& out, int k) { out << "10<tspan dy=\"-5\" font-size=\"8\">" << k << "</tspan>"; }

// One output group's scatter: each case's error (log) against its condition number (log), with the
// tolerance line base + c kappa and the approximate bound; cases without outputs in a strip at the top,
// exact outputs in a strip at the bottom. One circle per case.
void scatter(std::ostream& out, const Report& r, int g) {
  const Grading& gr = r.grading;
  const double base = gr.policy.base, c = gr.policy.c, bound = approximate_bound(gr.dtype);
  constexpr double width = 760, height = 430, left = 74, right = 744, top = 20, bottom = 372;
  constexpr double inf_band = top + 9, log_top = top + 26, log_bottom = bottom - 26, zero_band = bottom - 9;

  double kmin = std::numeric_limits<double>::infinity(), kmax = 0;
  double emin = std::numeric_limits<double>::infinity(), emax = 0;
  int above = 0, approximate = 0, no_output = 0, zero = 0;
  for (const CaseOutcome& o : r.outcomes) {
    const double k = o.kappa[g], e = o.error[g];
    if (std::isfinite(k) && k > 0) kmin = std::min(kmin, k), kmax = std::max(kmax, k);
    if (!std::isfinite(e)) ++no_output;
    else if (e == 0) ++zero;
    else emin = std::min(emin, e), emax = std::max(emax, e);
    if (std::isfinite(e) && e > o.tolerance[g]) ++(e <= bound * (1 + k) ? approximate : above);
  }
  if (!(kmin <= kmax)) kmin = kmax = 1;
  int xlo = static_cast<int>(std::floor(std::log10(kmin))), xhi = static_cast<int>(std::ceil(std::log10(kmax)));
  if (xhi <= xlo) xhi = xlo + 1;
  const double tol_lo = base + c * std::pow(10.0, xlo), tol_hi = base + c * std::pow(10.0, xhi);
  double ylo_value = std::min(emin, tol_lo), yhi_value = std::max(emax, tol_hi);
  if (above + approximate > 0) yhi_value = std::max(yhi_value, bound * (1 + std::pow(10.0, xlo)));
  int ylo = static_cast<int>(std::floor(std::log10(std::max(ylo_value, 1e-6))));
  int yhi = static_cast<int>(std::ceil(std::log10(std::min(yhi_value, 1e300))));
  if (yhi <= ylo) yhi = ylo + 1;

  const auto x_of = [&](double log_k) { return left + (log_k - xlo) / (xhi - xlo) * (right - left); };
  const auto y_of = [&](double log_e) { return log_bottom - (log_e - ylo) / (yhi - ylo) * (log_bottom - log_top); };
  const auto x_case = [&](double k) {
    if (!(k > 0)) return left;
    return x_of(std::clamp(std::log10(k), static_cast<double>(xlo), static_cast<double>(xhi)));
  };

  out << "<svg class=\"scatter\" data-group=\"" << group_name(r.grading, g) << "\" width=\"" << width << "\" height=\""
      << height << "\" viewBox=\"0 0 " << width << ' ' << height << "\" role=\"img\">\n";
  // Grid and ticks.
  const int xstep = label_step(xlo, xhi), ystep = label_step(ylo, yhi);
  for (int k = xlo; k <= xhi; ++k) {
    const std::string x = px(x_of(k));
    out << "<line class=\"grid\" x1=\"" << x << "\" y1=\"" << top << "\" x2=\"" << x << "\" y2=\"" << bottom << "\"/>";
    if ((k - xlo) % xstep == 0) {
      out << "<text x=\"" << x << "\" y=\"" << bottom + 16 << "\" text-anchor=\"middle\">";
      power_of_ten(out, k);
      out << "</text>";
    }
    out << '\n';
  }
  for (int k = ylo; k <= yhi; ++k) {
    const std::string y = px(y_of(k));
    out << "<line class=\"grid\" x1=\"" << left << "\" y1=\"" << y << "\" x2=\"" << right << "\" y2=\"" << y << "\"/>";
    if ((k - ylo) % ystep == 0) {
      out << "<text x=\"" << left - 6 << "\" y=\"" << px(y_of(k) + 4) << "\" text-anchor=\"end\">";
      power_of_ten(out, k);
      out << "</text>";
    }
    out << '\n';
  }
  out << "<line class=\"band\" x1=\"" << left << "\" y1=\"" << inf_band + 9 << "\" x2=\"" << right << "\" y2=\""
      << inf_band + 9 << "\"/><text x=\"" << left - 6 << "\" y=\"" << inf_band + 4
      << "\" text-anchor=\"end\">inf</text>\n";
  out << "<line class=\"band\" x1=\"" << left << "\" y1=\"" << zero_band - 9 << "\" x2=\"" << right << "\" y2=\""
      << zero_band - 9 << "\"/><text x=\"" << left - 6 << "\" y=\"" << zero_band + 4
      << "\" text-anchor=\"end\">0</text>\n";
  out << "<rect class=\"axis\" x=\"" << left << "\" y=\"" << top << "\" width=\"" << right - left << "\" height=\""
      << bottom - top << "\"/>\n";
  out << "<text x=\"" << (left + right) / 2 << "\" y=\"" << bottom + 36 << "\" text-anchor=\"middle\">condition "
      << "number &#954;<tspan dy=\"3\" font-size=\"8\">" << group_name(r.grading, g) << "</tspan></text>\n";
  out << "<text transform=\"rotate(-90)\" x=\"" << -(top + bottom) / 2 << "\" y=\"16\" text-anchor=\"middle\">"
      << "normwise error of " << group_name(r.grading, g) << ", units of u</text>\n";

  // The lines a + b kappa, where they are inside the plot (both increase with kappa).
  const auto line = [&](double a, double b, const char* css) {
    double x0 = xlo, x1 = xhi;
    const double lo_k = (std::pow(10.0, ylo) - a) / b, hi_k = (std::pow(10.0, yhi) - a) / b;
    if (!(hi_k > 0)) return false;
    if (lo_k > 0) x0 = std::max(x0, std::log10(lo_k));
    x1 = std::min(x1, std::log10(hi_k));
    if (!(x1 > x0)) return false;
    out << "<polyline class=\"" << css << "\" points=\"";
    constexpr int samples = 64;
    for (int i = 0; i <= samples; ++i) {
      const double lx = x0 + (x1 - x0) * i / samples;
      const double ly =
          std::clamp(std::log10(a + b * std::pow(10.0, lx)), static_cast<double>(ylo), static_cast<double>(yhi));
      out << (i ? " " : "") << px(x_of(lx)) << ',' << px(y_of(ly));
    }
    out << "\"/>\n";
    return true;
  };
  const bool tolerance_shown = c > 0 ? line(base, c, "tol") : false;
  const bool bound_shown = line(bound, bound, "apx");

  // The cases.
  for (const CaseOutcome& o : r.outcomes) {
    const double k = o.kappa[g], e = o.error[g];
    const std::string cx = px(x_case(k));
    const char* css = "m";
    double cy = inf_band;
    if (std::isfinite(e)) {
      css = e <= o.tolerance[g] ? "p" : e <= bound * (1 + k) ? "a" : "f";
      cy = e == 0 ? zero_band : y_of(std::clamp(std::log10(e), static_cast<double>(ylo), static_cast<double>(yhi)));
    }
    out << "<circle class=\"" << css << "\" cx=\"" << cx << "\" cy=\"" << px(cy) << "\" r=\"2.6\"><title>"
        << escape(o.id) << ": ";
    if (o.status != Status::ok) out << status_name(o.status);
    else out << "error " << num(e) << ", tolerance " << num(o.tolerance[g]);
    out << ", \u03ba " << num(k) << "; case tier " << tier_name(o.tier) << "</title></circle>\n";
  }
  out << "</svg>\n<div class=\"note\"><span class=\"key p\"></span>within the tolerance<span class=\"key a\"></span>"
         "approximate<span class=\"key f\"></span>outside the approximate bound<span class=\"key m\"></span>"
         "missing or non-finite (top strip)";
  if (tolerance_shown) out << "<span class=\"line\"></span>" << num(base) << " + " << num(c) << " &kappa;";
  out << "<span class=\"line apx\"></span>approximate bound " << num(bound) << " (1 + &kappa;)";
  if (!bound_shown) out << " (above the plot)";
  out << "<br>" << r.outcomes.size() << " cases: " << above + approximate << " outside the tolerance (" << approximate
      << " within the approximate bound), " << no_output << " missing or non-finite, " << zero
      << " exact (bottom strip).</div>\n";
}

void scatters(std::ostream& out, const Report& r) {
  out << "<section id=\"scatter\"><h2>Error against condition number</h2>\n<p class=\"note\">One point per case "
         "(hover for its id); the tolerance grows with the condition number &kappa;, the error an accurate "
         "algorithm makes too.</p>\n";
  for (int g = 0; g < 3; ++g) {
    out << "<div class=\"card\"><h3 id=\"scatter-" << group_name(r.grading, g) << "\">" << group_name(r.grading, g)
        << "</h3>\n";
    if (r.grading.given[g]) scatter(out, r, g);
    else out << "<p class=\"nc\">not checked: the candidate did not give " << group_name(r.grading, g) << ".</p>\n";
    out << "</div>\n";
  }
  out << "</section>\n";
}

// Colour of t in [0, 1] on a sequential yellow-orange-red scale.
std::string ramp(double t) {
  static constexpr double stops[][3] = {{255, 255, 204}, {254, 217, 118}, {253, 141, 60}, {227, 26, 28}, {128, 0, 38}};
  constexpr int n = 5;
  t = std::clamp(t, 0.0, 1.0) * (n - 1);
  const int i = std::min(static_cast<int>(t), n - 2);
  const double f = t - i;
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x",
                static_cast<int>(std::lround(stops[i][0] * (1 - f) + stops[i + 1][0] * f)),
                static_cast<int>(std::lround(stops[i][1] * (1 - f) + stops[i + 1][1] * f)),
                static_cast<int>(std::lround(stops[i][2] * (1 - f) + stops[i + 1][2] * f)));
  return buffer;
}

// The 12 x 12 map of the case's Hessian errors |got - expected| / (u ||expected||), in the contract's order.
void hessian_map(std::ostream& out, const Report& r, const Expected& e, const CandidateResult& got,
                 const CaseOutcome& o) {
  const double u = unit_roundoff(r.grading.dtype);
  const double norm = oracle::scaled_norm(e.values.hess.data(), 144);
  const double denominator = u * (norm > 0 ? norm : e.conditioning.scale[2]);
  std::array<double, 144> v{};
  double vmin = std::numeric_limits<double>::infinity(), vmax = 0;
  for (int i = 0; i < 144; ++i) {
    const double d = std::fabs(got.hess[i] - e.values.hess[i]);
    v[i] = d == 0 ? 0 : d / denominator;
    if (v[i] > 0 && std::isfinite(v[i])) vmin = std::min(vmin, v[i]), vmax = std::max(vmax, v[i]);
  }
  // The scale reaches the case's Hessian tolerance at least, so that errors far below it stay pale.
  const double tol = o.tolerance[2];
  const double reach = std::isfinite(tol) ? std::max({vmax, tol, 1.0}) : std::max(vmax, 1.0);
  int chi = static_cast<int>(std::ceil(std::log10(reach)));
  int clo = vmax > 0 ? static_cast<int>(std::floor(std::log10(vmin))) : -1;
  clo = std::clamp(clo, std::max(chi - 30, -3), chi - 1);  // below 10^-3 units: the palest colour
  const auto colour = [&](double value) {
    if (value == 0) return std::string("#ffffff");
    if (!std::isfinite(value)) return std::string("#000000");
    return ramp((std::log10(value) - clo) / (chi - clo));
  };

  const bool reordered = r.stencil != contract_stencil;
  constexpr double cell = 30;
  const double left = reordered ? 100 : 50, top = reordered ? 46 : 30;
  const double size = 12 * cell, width = left + size + 50, legend_y = top + size + 24;
  const double height = legend_y + 56;
  out << "<svg class=\"hessmap\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << ' '
      << height << "\" role=\"img\">\n";
  for (int i = 0; i < 12; ++i) {
    const double mid = (i + 0.5) * cell;
    out << "<text x=\"" << left - 6 << "\" y=\"" << px(top + mid + 4) << "\" text-anchor=\"end\">" << variable(i);
    if (reordered)
      out << " <tspan fill=\"#5b636b\">(v" << candidate_variable(r.stencil, i) / 3 << '.' << "xyz"[i % 3]
          << ")</tspan>";
    out << "</text><text x=\"" << px(left + mid) << "\" y=\"" << top - 8 << "\" text-anchor=\"middle\">" << variable(i)
        << "</text>";
    if (reordered)
      out << "<text x=\"" << px(left + mid) << "\" y=\"" << top - 22 << "\" text-anchor=\"middle\" fill=\"#5b636b\">v"
          << candidate_variable(r.stencil, i) / 3 << '.' << "xyz"[i % 3] << "</text>";
    out << '\n';
  }
  for (int row = 0; row < 12; ++row)
    for (int col = 0; col < 12; ++col) {
      const int i = 12 * row + col;
      out << "<rect class=\"cell\" x=\"" << px(left + col * cell) << "\" y=\"" << px(top + row * cell) << "\" width=\""
          << cell << "\" height=\"" << cell << "\" fill=\"" << colour(v[i]) << "\" stroke=\"#e6e8eb\"><title>hess["
          << row << "][" << col << "] (" << variable(row) << ", " << variable(col) << "): expected "
          << exact(e.values.hess[i]) << ", got " << exact(got.hess[i]) << "; |got &#8722; expected| " << num(v[i])
          << " u ||hess||</title></rect>\n";
    }
  for (int b = 0; b <= 4; ++b) {
    out << "<line x1=\"" << px(left) << "\" y1=\"" << px(top + b * 3 * cell) << "\" x2=\"" << px(left + size)
        << "\" y2=\"" << px(top + b * 3 * cell) << "\" stroke=\"#1d2125\"/><line x1=\"" << px(left + b * 3 * cell)
        << "\" y1=\"" << px(top) << "\" x2=\"" << px(left + b * 3 * cell) << "\" y2=\"" << px(top + size)
        << "\" stroke=\"#1d2125\"/>\n";
  }
  // The legend: the decades clo..chi, exact zeros, the case's Hessian tolerance.
  const double bar_left = left + 70, bar_width = size - 90;
  out << "<rect x=\"" << px(left) << "\" y=\"" << px(legend_y) << "\" width=\"16\" height=\"14\" fill=\"#ffffff\" "
      << "stroke=\"#5b636b\"/><text x=\"" << px(left + 22) << "\" y=\"" << px(legend_y + 11) << "\">exact</text>\n";
  out << "<text x=\"" << px(bar_left) << "\" y=\"" << px(legend_y - 6)
      << "\">|got &#8722; expected| / (u ||expected hess||), log scale</text>\n";
  constexpr int steps = 40;
  for (int s = 0; s < steps; ++s)
    out << "<rect x=\"" << px(bar_left + bar_width * s / steps) << "\" y=\"" << px(legend_y) << "\" width=\""
        << px(bar_width / steps + 0.5) << "\" height=\"14\" fill=\"" << ramp((s + 0.5) / steps) << "\"/>";
  out << '\n';
  const int step = std::max(1, (chi - clo + 6) / 7);
  for (int k = clo; k <= chi; k += step) {
    const double x = bar_left + bar_width * (k - clo) / (chi - clo);
    out << "<line x1=\"" << px(x) << "\" y1=\"" << px(legend_y + 14) << "\" x2=\"" << px(x) << "\" y2=\""
        << px(legend_y + 18) << "\" stroke=\"#5b636b\"/><text x=\"" << px(x) << "\" y=\"" << px(legend_y + 30)
        << "\" text-anchor=\"middle\">";
    power_of_ten(out, k);
    out << "</text>";
  }
  if (tol > 0 && std::log10(tol) >= clo && std::log10(tol) <= chi) {
    const double x = bar_left + bar_width * (std::log10(tol) - clo) / (chi - clo);
    out << "<line x1=\"" << px(x) << "\" y1=\"" << px(legend_y - 4) << "\" x2=\"" << px(x) << "\" y2=\""
        << px(legend_y + 18) << "\" stroke=\"#1d2125\" stroke-width=\"2\"/><text x=\"" << px(x) << "\" y=\""
        << px(legend_y + 44) << "\" text-anchor=\"middle\">hess tolerance " << num(tol) << "</text>";
  }
  out << "\n</svg>\n<p class=\"note\">Each cell: |got &minus; expected| of that Hessian entry in units of u "
         "relative to ||expected hess|| = "
      << exact(norm) << " (log colour scale; the normwise error " << num(o.error[2])
      << " is the root of the sum of their squares). Rows and columns in the contract's order x0.x &hellip; x3.z";
  if (reordered)
    out << "; in grey your kernel's labels, vK its K-th vertex (X[:, 3K:3K+3]), stencil "
        << escape(stencil_name(r.stencil));
  out << ". Hover a cell for the expected and got values.</p>\n";
}

// Theta and the gradient, entry by entry, expected against got.
void entries(std::ostream& out, const Report& r, const Expected& e, const CandidateResult& got) {
  const double u = unit_roundoff(r.grading.dtype);
  out << "<table><tr><th class=\"l\">output</th><th>expected</th><th>got</th><th>|got &minus; expected| / (u "
         "||expected||)</th></tr>\n";
  for (int g = 0; g < 2; ++g) {
    if (!r.grading.given[g]) continue;
    const double* want = group_values(e.values, g);
    const double* have = group_values(got, g);
    const double norm = oracle::scaled_norm(want, group_sizes[g]);
    const double denominator = u * (norm > 0 ? norm : e.conditioning.scale[g]);
    for (std::size_t i = 0; i < group_sizes[g]; ++i) {
      const double d = std::fabs(have[i] - want[i]);
      out << "<tr><td class=\"l\">"
          << (g == 0 ? std::string("theta") : "grad[" + std::to_string(i) + "] " + variable(static_cast<int>(i)))
          << "</td><td>" << exact(want[i]) << "</td><td>" << exact(have[i]) << "</td><td>"
          << num(d == 0 ? 0 : d / denominator) << "</td></tr>\n";
    }
  }
  out << "</table>\n";
}

// Numbers as a Python list, `per_line` a line, its lines after the first indented by `indent` spaces (the
// column of the list's first number).
std::string python_list(const double* v, std::size_t n, std::size_t per_line, std::size_t indent) {
  std::string out = "[";
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += i % per_line ? ", " : ",\n" + std::string(indent, ' ');
    out += python(v[i]);
  }
  return out + ']';
}

// A row-major 12 x 12 matrix as a Python list of its rows, 4 numbers a line, `indent` as above.
std::string python_matrix(const double* v, std::size_t indent) {
  std::string out = "[";
  for (std::size_t row = 0; row < 12; ++row)
    out += (row ? ",\n" + std::string(indent, ' ') : std::string()) + python_list(v + 12 * row, 12, 4, indent + 1);
  return out + ']';
}

// The reproducer: the inputs, the expected outputs, a pytest test of the user's function on this case.
void reproducer(std::ostream& out, const Report& r, const Expected& e, const CaseOutcome& o) {
  const Grading& gr = r.grading;
  const bool f32 = gr.dtype == Dtype::float32;
  const std::array<double, 12> xc = candidate_order(e.input.x, r.stencil);
  out << "<h3 id=\"reproducer\">Reproducer</h3>\n<p>The 12 inputs, in the contract's order (x0.x, x0.y, &hellip;, "
         "x3.z):</p>\n<pre>";
  out << python_list(e.input.x.data(), 12, 3, 1) << "</pre>\n<p>In your kernel's order (stencil "
      << escape(stencil_name(r.stencil)) << "):</p>\n<pre>" << python_list(xc.data(), 12, 3, 1) << "</pre>\n";
  std::array<double, 12> rc{};  // a bending term's rest hinge, in its order
  if (e.input.rest) {
    rc = candidate_order(*e.input.rest, r.stencil);
    out << "<p>The rest hinge R, the contract's order:</p>\n<pre>" << python_list(e.input.rest->data(), 12, 3, 1)
        << "</pre>\n<p>In your kernel's order:</p>\n<pre>" << python_list(rc.data(), 12, 3, 1) << "</pre>\n";
  }
  out << "<p>Expected outputs, the contract's order (every number exact"
      << (f32 ? ": the exact value correctly rounded to float32" : ": the double nearest the exact value")
      << "):</p>\n<pre>" << group_name(gr, 0) << " = " << exact(e.values.theta) << "\ngrad = ";
  out << python_list(e.values.grad.data(), 12, 3, 8) << "\nhess = " << python_matrix(e.values.hess.data(), 8)
      << "</pre>\n";

  // The expected outputs in the candidate's variable order, as its function returns them.
  std::array<double, 12> grad{};
  std::array<double, 144> hess{};
  for (int a = 0; a < 12; ++a) {
    grad[a] = e.values.grad[contract_variable(r.stencil, a)];
    for (int b = 0; b < 12; ++b)
      hess[12 * a + b] = e.values.hess[12 * contract_variable(r.stencil, a) + contract_variable(r.stencil, b)];
  }
  std::string outputs;
  for (int g = 0; g < 3; ++g)
    if (gr.given[g]) outputs += std::string(outputs.empty() ? "" : ", ") + "\"" + group_name(r.grading, g) + "\"";
  const char* dtype = f32 ? "np.float32" : "np.float64";

  std::string code;
  const auto put = [&](const std::string& s) { code += s; };
  const bool energy = e.input.rest.has_value();
  put(energy ? "import numpy as np\n\nfrom my_module import my_term  # your function: my_term(X, R), both of shape (n, "
               "12)\n\n"
             : "import numpy as np\n\nfrom my_module import my_kernel  # your function: my_kernel(X), X of shape (n, "
               "12)\n\n");
  put("# hinge conform: case " + e.input.id + ", " + dtype_name(gr.dtype) + ", stencil " + stencil_name(r.stencil) +
      ".\n");
  put("# Each output group passes when ||got - expected|| / (u ||expected||) <= BASE + C * KAPPA[group]\n");
  put("# (relative to SCALE[group] where the expected group is zero).\n");
  put(std::string("U = 2.0 ** ") + (f32 ? "-24" : "-53") + "\nBASE, C = " + exact(gr.policy.base) + ", " +
      exact(gr.policy.c) + "\nOUTPUTS = (" + outputs + (outputs.find(',') == std::string::npos ? ",)" : ")") +
      "  # the order of a returned tuple\n");
  put("X = np.array([" + python_list(xc.data(), 12, 3, 15) + "], dtype=" + dtype + ")  # one hinge, your order\n");
  if (energy) put("R = np.array([" + python_list(rc.data(), 12, 3, 15) + "], dtype=" + dtype + ")  # its rest hinge\n");
  put("EXPECTED = {  # your variable order\n");
  if (gr.given[0]) put("    \"" + std::string(group_name(gr, 0)) + "\": np.array([" + python(e.values.theta) + "]),\n");
  if (gr.given[1]) put("    \"grad\": np.array(" + python_list(grad.data(), 12, 3, 22) + "),\n");
  if (gr.given[2]) put("    \"hess\": np.array(" + python_matrix(hess.data(), 22) + "),\n");
  put("}\nKAPPA = {");
  for (int g = 0, n = 0; g < 3; ++g)
    if (gr.given[g]) put((n++ ? ", \"" : "\"") + std::string(group_name(r.grading, g)) + "\": " + python(o.kappa[g]));
  put("}\nSCALE = {");
  for (int g = 0, n = 0; g < 3; ++g)
    if (gr.given[g])
      put((n++ ? ", \"" : "\"") + std::string(group_name(r.grading, g)) + "\": " + python(e.conditioning.scale[g]));
  put("}\n\n\n");
  put("def _norm(v):\n"
      "    v = np.asarray(v, dtype=np.float64).ravel()\n"
      "    m = np.max(np.abs(v))\n"
      "    return m if m == 0 or not np.isfinite(m) else m * np.linalg.norm(v / m)\n\n\n");
  put(energy
          ? "def test_worst_case():\n    out = my_term(X.copy(), R.copy())  # with batch=False: my_term(X[0].copy(), "
            "R[0].copy())\n"
          : "def test_worst_case():\n    out = my_kernel(X.copy())  # with batch=False: my_kernel(X[0].copy())\n");
  put("    got = {k: out[k] for k in OUTPUTS} if isinstance(out, dict) else dict(zip(OUTPUTS, out))\n"
      "    for name, expected in EXPECTED.items():\n");
  put(std::string("        g = np.asarray(got[name]") + (f32 ? ").astype(np.float32)" : ")") +
      ".astype(np.float64).reshape(expected.shape)\n");
  put("        norm = _norm(expected)\n"
      "        error = _norm(g - expected) / (U * (norm if norm > 0 else SCALE[name]))\n"
      "        tolerance = BASE + C * KAPPA[name]\n"
      "        assert error <= tolerance, f\"{name}: error {error:.3g} units of u > tolerance {tolerance:.3g}\"\n");
  out << "<p>A pytest test calling your function on this case (rename <code>my_module.my_kernel</code>):</p>\n<pre "
         "class=\"pytest\">"
      << escape(code) << "</pre>\n";
}

void worst_case(std::ostream& out, const Report& r) {
  out << "<section id=\"worst\"><h2>Worst failing case</h2>\n";
  const Chosen chosen = choose_worst_failing(r);
  if (!chosen.found) {
    out << "<p>Every case passes: no failing case to map or reproduce.</p>\n</section>\n";
    return;
  }
  const std::size_t i = chosen.index;
  const CaseOutcome& o = r.outcomes[i];
  if (!chosen.with_outputs) {
    int missing = 0, nonfinite = 0;
    for (const CaseOutcome& c : r.outcomes)
      if (!c.pass) (c.status == Status::nonfinite ? nonfinite : missing) += 1;
    out << "<p>No failing case has outputs to compare: " << missing << " missing, " << nonfinite
        << " non-finite. The first of them, <b class=\"worst-id\">" << escape(o.id) << "</b> ("
        << status_name(o.status);
    if (i < r.results.size() && !r.results[i].error.empty()) out << ": " << escape(r.results[i].error);
    out << "), is reproduced below.</p>\n";
  } else {
    out << "<p><b class=\"worst-id\">" << escape(o.id) << "</b> (" << escape(o.category)
        << "): " << group_name(r.grading, o.group) << " error " << num(o.error[o.group]) << " units of u, tolerance "
        << num(o.tolerance[o.group]) << " (&kappa; " << num(o.kappa[o.group]) << "), " << num(o.ratio)
        << " times the tolerance; tier " << tier_name(o.tier) << ". Largest difference at "
        << group_name(r.grading, o.group);
    if (o.group > 0) out << '[' << o.entry << ']';
    out << ": expected " << exact(o.expected_value) << ", got " << exact(o.candidate_value) << ".</p>\n";
    out << "<table><tr><th class=\"l\">group</th><th>error</th><th>tolerance</th><th>&kappa;</th><th>error / "
           "tolerance</th></tr>\n";
    for (int g = 0; g < 3; ++g) {
      out << "<tr><td class=\"l\">" << group_name(r.grading, g) << "</td>";
      if (!r.grading.given[g]) out << "<td class=\"nc\" colspan=\"4\">not checked</td></tr>\n";
      else
        out << "<td>" << num(o.error[g]) << "</td><td>" << num(o.tolerance[g]) << "</td><td>" << num(o.kappa[g])
            << "</td><td>" << num(o.error[g] / o.tolerance[g]) << "</td></tr>\n";
    }
    out << "</table>\n";
  }
  if (i >= r.expected.size()) {
    out << "</section>\n";
    return;
  }
  const Expected& e = r.expected[i];
  if (chosen.with_outputs && i < r.results.size()) {
    const CandidateResult& got = r.results[i];
    if (r.grading.given[2]) {
      out << "<h3 id=\"hessian-map\">Hessian errors</h3>\n";
      hessian_map(out, r, e, got, o);
    } else {
      out << "<p class=\"nc\">The Hessian was not checked: no map.</p>\n";
    }
    if (r.grading.given[0] || r.grading.given[1]) {
      out << "<h3>Theta and gradient</h3>\n";
      entries(out, r, e, got);
    }
  }
  reproducer(out, r, e, o);
  out << "</section>\n";
}

}  // namespace

void write_html_report(std::ostream& out, const Report& report) {
  out << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>hinge conform: "
      << (report.passed ? "PASS" : "FAIL") << ", " << escape(report.candidate) << "</title>\n<style>" << style
      << "</style></head>\n<body><main>\n";
  out << "<nav><a href=\"#categories\">categories</a><a href=\"#scatter\">error against &kappa;</a><a "
         "href=\"#worst\">worst failing case</a>";
  if (!report.diagnosis.empty()) out << "<a href=\"#diagnosis\">diagnosis</a>";
  out << "</nav>\n";
  header(out, report);
  diagnosis(out, report);
  category_table(out, report);
  scatters(out, report);
  worst_case(out, report);
  out << (report.grading.energy
              ? "<footer class=\"note\"><p>hinge conform: a bending term's energy, gradient and Hessian against "
                "certified values (docs/energy-conformance.md).</p></footer>\n"
              : "<footer class=\"note\"><p>hinge conform: the theta, gradient and Hessian of the bend angle of "
                "Tamstorf &amp; Grinspun 2013 against certified values (docs/conformance.md).</p></footer>\n")
      << "</main></body></html>\n";
}

}  // namespace hinge::conformance
