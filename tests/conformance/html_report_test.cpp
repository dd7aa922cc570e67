// The HTML report (hinge/conformance/html_report.hpp) of graded runs made from a few conformance inputs:
// it requests nothing, names every category with its tier, maps and reproduces the worst failing case only
// when a case fails, escapes its text, and draws one point per graded case in each scatter.
// HINGE_HTML_REPORT_SAMPLE=FILE writes the failing run's page to FILE, to look at.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "hinge/conformance/html_report.hpp"

namespace hinge::conformance {
namespace {

// Two cases of each of five categories, with their certified outputs.
const std::vector<Expected>& cases() {
  static const std::vector<Expected> all = [] {
    const std::vector<std::string> wanted{"well-shaped", "rotations", "scales", "near-flat", "needles"};
    std::map<std::string, int> taken;
    std::vector<Expected> out;
    for (const Case& c : inputs())
      if (std::find(wanted.begin(), wanted.end(), c.category) != wanted.end() && taken[c.category]++ < 2)
        out.push_back(expected(c));
    return out;
  }();
  return all;
}

CandidateResult exact_result(const Expected& e) {
  CandidateResult r;
  r.status = CandidateResult::Status::ok;
  r.theta = e.values.theta;
  r.grad = e.values.grad;
  r.hess = e.values.hess;
  return r;
}

// The certified outputs everywhere: every category correctly rounded.
Report passing_report(const std::string& candidate = "exact outputs") {
  std::vector<CandidateResult> results;
  for (const Expected& e : cases()) results.push_back(exact_result(e));
  return make_report(candidate, cases(), results, Grading{});
}

// Rotations one ulp off in theta (a better tier than fail), scales with a Hessian entry off by a relative
// 1e-3 (one case) and 1e-6 (the other), the first near-flat case missing, the rest exact.
Report failing_report(const std::string& candidate = "perturbed outputs", const Grading& grading = {},
                      const Stencil& stencil = contract_stencil) {
  std::vector<CandidateResult> results;
  int scales = 0;
  bool missing = false;
  for (const Expected& e : cases()) {
    CandidateResult r = exact_result(e);
    if (e.input.category == "rotations") r.theta = std::nextafter(r.theta, 4.0);
    if (e.input.category == "scales") r.hess[13] *= scales++ == 0 ? 1.001 : 1.000001;
    if (e.input.category == "near-flat" && !missing) {
      r = CandidateResult{};
      r.error = "cannot evaluate";
      missing = true;
    }
    results.push_back(r);
  }
  return make_report(candidate, cases(), results, grading, stencil);
}

std::string page(const Report& report) {
  std::ostringstream out;
  write_html_report(out, report);
  return out.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The references of a page that point anywhere but a `#` fragment or a `data:` URL: every src=, href=,
// url( and @import, with what follows it.
std::vector<std::string> outside_references(const std::string& html) {
  const std::string text = lower(html);
  std::vector<std::string> bad;
  const std::regex reference(
      R"((\bsrc|\bhref|\bxlink:href)\s*=\s*["']?\s*([^"'\s>]*)|url\(\s*["']?\s*([^"')\s]*)|@import)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), reference); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    const std::string target = m[2].matched ? m[2].str() : m[3].matched ? m[3].str() : "";
    if (m.str().rfind("@import", 0) == 0 || !(target.rfind('#', 0) == 0 || target.rfind("data:", 0) == 0))
      bad.push_back(m.str());
  }
  return bad;
}

// The blocks of the page between `open` and `close`.
std::vector<std::string> blocks(const std::string& html, const std::string& open, const std::string& close) {
  std::vector<std::string> out;
  for (std::size_t at = html.find(open); at != std::string::npos; at = html.find(open, at + 1)) {
    const std::size_t end = html.find(close, at);
    out.push_back(html.substr(at, end == std::string::npos ? std::string::npos : end - at));
  }
  return out;
}

// The failing case with outputs and the largest error / tolerance.
const CaseOutcome* worst_failing(const Report& report) {
  const CaseOutcome* worst = nullptr;
  for (const CaseOutcome& o : report.outcomes)
    if (!o.pass && o.status == CandidateResult::Status::ok && (!worst || o.ratio > worst->ratio)) worst = &o;
  return worst;
}

TEST(HtmlReport, RequestsNothingButFragmentsAndDataUrls) {
  const std::string hostile = "x src=\"http://a/b.js\" href='//c' url(http://d) @import \"e.css\"";
  for (const Report& report :
       {passing_report(), failing_report(hostile), failing_report("reordered", Grading{}, Stencil{0, 3, 1, 2})}) {
    const std::string html = page(report);
    EXPECT_EQ(outside_references(html), std::vector<std::string>{}) << report.candidate;
    EXPECT_GT(count(html, "href=\"#"), 0u) << "the navigation links to fragments";
    const std::string text = lower(html);
    for (const char* element : {"<script", "<link", "<img", "<iframe", "<object", "<embed"})
      EXPECT_EQ(text.find(element), std::string::npos) << element;
    // No address at all, but in the hostile candidate's name (text, escaped).
    if (report.candidate != hostile) {
      EXPECT_EQ(text.find("://"), std::string::npos);
    }
  }
  // The checker itself finds what it looks for.
  EXPECT_EQ(outside_references("<img src=\"x.png\"><a href=\"#ok\"></a><i style=\"b:url('data:,')\"></i>").size(), 1u);
  EXPECT_EQ(outside_references("<style>@import 'a.css'; i{b:url(c.png)}</style>").size(), 2u);
}

TEST(HtmlReport, NamesEveryCategoryWithItsTier) {
  for (const Report& report : {passing_report(), failing_report()}) {
    const std::string html = page(report);
    const std::string table = blocks(html, "<section id=\"categories\">", "</table>").at(0);
    ASSERT_EQ(report.categories.size(), 5u);
    for (const CategorySummary& s : report.categories) {
      const std::string start = "<tr><td class=\"l\">" + s.category + "</td>";
      ASSERT_EQ(count(table, start), 1u) << s.category;
      const std::string row = blocks(table, start, "</tr>").at(0);
      EXPECT_NE(row.find(std::string(">") + tier_name(s.tier) + "</td>"), std::string::npos) << row;
    }
    EXPECT_NE(html.find(std::string("overall tier</dt><dd><span class=\"")), std::string::npos);
  }
  // The failing run's categories span the tiers: exact, one ulp off, outside the policy.
  std::map<std::string, Tier> tiers;
  for (const CategorySummary& s : failing_report().categories) tiers[s.category] = s.tier;
  EXPECT_EQ(tiers["well-shaped"], Tier::correctly_rounded);
  EXPECT_LT(tiers["rotations"], Tier::approximate);
  EXPECT_GE(tiers["scales"], Tier::approximate);
  EXPECT_EQ(tiers["near-flat"], Tier::fail);
}

TEST(HtmlReport, MapsAndReproducesTheWorstFailingCaseOnlyWhenOneFails) {
  const Report failing = failing_report();
  const CaseOutcome* worst = worst_failing(failing);
  ASSERT_NE(worst, nullptr);
  EXPECT_EQ(worst->category, "scales");
  const std::string html = page(failing);
  EXPECT_NE(html.find("class=\"worst-id\">" + worst->id + "</b>"), std::string::npos);
  EXPECT_EQ(count(html, "class=\"cell\""), 144u);
  EXPECT_NE(html.find("def test_worst_case"), std::string::npos);
  EXPECT_NE(html.find("dtype&#61;np.float64"), std::string::npos);

  const std::string passing = page(passing_report());
  EXPECT_EQ(count(passing, "class=\"cell\""), 0u);
  EXPECT_EQ(passing.find("worst-id"), std::string::npos);
  EXPECT_EQ(passing.find("def test_worst_case"), std::string::npos);
  for (const CaseOutcome& o : failing.outcomes)
    if (!o.pass) {
      EXPECT_EQ(passing.find(">" + o.id + "<"), std::string::npos) << o.id;
    }
}

TEST(HtmlReport, WithoutAFailingCaseWithOutputsSaysSoAndDrawsNoMap) {
  std::vector<CandidateResult> results;
  for (const Expected& e : cases()) {
    CandidateResult r = exact_result(e);
    if (e.input.category == "needles") {
      r.grad[0] = std::numeric_limits<double>::infinity();
      check_finite(r);
    }
    results.push_back(r);
  }
  const Report report = make_report("non-finite on needles", cases(), results, Grading{});
  ASSERT_FALSE(report.passed);
  const std::string html = page(report);
  EXPECT_NE(html.find("No failing case has outputs to compare"), std::string::npos);
  EXPECT_EQ(count(html, "class=\"cell\""), 0u);
  EXPECT_NE(html.find("def test_worst_case"), std::string::npos) << "the reproducer of a case without outputs";
}

TEST(HtmlReport, EscapesTextAndShowsNonFiniteNumbersAsInfOrNa) {
  std::vector<Expected> odd = cases();
  odd[0].input.id = "well-shaped/<b>&\"00\"";
  std::vector<CandidateResult> results;
  for (const Expected& e : odd) results.push_back(exact_result(e));
  results[0].theta = -results[0].theta;
  Grading grading;
  grading.given = {true, true, false};
  const Report report =
      make_report("<script>alert('owned')</script> & co", odd, results, grading, contract_stencil, "quick");
  const std::string html = page(report);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(html.find("&lt;script&gt;alert&#40;&#39;owned&#39;&#41;&lt;/script&gt; &amp; co"), std::string::npos);
  EXPECT_EQ(html.find("<b>&\"00\""), std::string::npos);
  EXPECT_NE(html.find("well-shaped/&lt;b&gt;&amp;&quot;00&quot;"), std::string::npos);
  // The Hessian, not given, is "not checked", its NaN errors never printed.
  EXPECT_NE(html.find("not checked"), std::string::npos);
  EXPECT_FALSE(std::regex_search(html, std::regex(R"(\bnan\b)", std::regex::icase)));
  const Report missing = failing_report();
  const std::string with_missing = page(missing);
  EXPECT_NE(with_missing.find("<td>inf</td>"), std::string::npos);
  EXPECT_FALSE(std::regex_search(with_missing, std::regex(R"(\bnan\b)", std::regex::icase)));
}

TEST(HtmlReport, DrawsOnePointPerGradedCaseInEachScatter) {
  for (const std::array<bool, 3>& given : {std::array<bool, 3>{true, true, true}, {true, true, false}}) {
    Grading grading;
    grading.given = given;
    const Report report = failing_report("perturbed", grading);
    const std::string html = page(report);
    const std::vector<std::string> plots = blocks(html, "<svg class=\"scatter\"", "</svg>");
    EXPECT_EQ(plots.size(), static_cast<std::size_t>(std::count(given.begin(), given.end(), true)));
    for (const std::string& plot : plots) {
      EXPECT_EQ(count(plot, "<circle "), report.outcomes.size());
      EXPECT_EQ(count(plot, "<title>"), report.outcomes.size());
    }
    if (const char* path = std::getenv("HINGE_HTML_REPORT_SAMPLE"); path && given[2]) std::ofstream(path) << html;
  }
}

TEST(HtmlReport, StatesTheUnitAndThePolicyOfItsDtype) {
  Grading grading;
  grading.dtype = Dtype::float32;
  grading.policy = {8, 2};
  const std::string html = page(failing_report("in float32", grading));
  for (const char* text : {"float32: every error in units of u = 2<sup>-24</sup>", "at most 8 + 2 &kappa;",
                           "within 2<sup>-8</sup> (1 + &kappa;) relative", "dtype&#61;np.float32", "U &#61; 2.0 ** -24",
                           "BASE, C &#61; 8, 2", ".astype&#40;np.float32&#41;"})
    EXPECT_NE(html.find(text), std::string::npos) << text;
}

TEST(HtmlReport, WritesAPageForAnEmptyReport) {
  const std::string html = page(Report{});
  EXPECT_NE(html.find("</html>"), std::string::npos);
  EXPECT_EQ(count(html, "<circle "), 0u);
  EXPECT_EQ(outside_references(html), std::vector<std::string>{});
}

// The pytest snippet of a page, as its reader copies it.
std::string snippet(const std::string& html) {
  const std::string open = "<pre class=\"pytest\">";
  const std::size_t at = html.find(open), end = html.find("</pre>", at);
  if (at == std::string::npos || end == std::string::npos) return "";
  std::string code = html.substr(at + open.size(), end - at - open.size());
  for (const auto& [reference, ch] : std::vector<std::pair<std::string, std::string>>{{"&#40;", "("},
                                                                                      {"&#41;", ")"},
                                                                                      {"&#61;", "="},
                                                                                      {"&#64;", "@"},
                                                                                      {"&quot;", "\""},
                                                                                      {"&#39;", "'"},
                                                                                      {"&lt;", "<"},
                                                                                      {"&gt;", ">"},
                                                                                      {"&amp;", "&"}})
    for (std::size_t p = code.find(reference); p != std::string::npos; p = code.find(reference, p + 1))
      code.replace(p, reference.size(), ch);
  return code;
}

// The numbers of the Python list that follows `key` in `code`.
std::vector<double> numbers_after(const std::string& code, const std::string& key) {
  std::vector<double> out;
  std::size_t at = code.find(key);
  if (at == std::string::npos) return out;
  at = code.find('[', at);
  const std::size_t end = code.find(']', at);
  for (const char* p = code.c_str() + at + 1; p < code.c_str() + end;) {
    char* next = nullptr;
    const double v = std::strtod(p, &next);
    if (next == p) {
      ++p;
    } else {
      out.push_back(v);
      p = next;
    }
  }
  return out;
}

TEST(HtmlReport, NamesTheCandidatesLabelsWhenItsStencilDiffers) {
  const Stencil stencil{0, 3, 1, 2};
  const Report report = failing_report("reordered", Grading{}, stencil);
  const std::string html = page(report);
  EXPECT_EQ(count(html, "class=\"cell\""), 144u);
  EXPECT_NE(html.find("your kernel's labels"), std::string::npos);
  EXPECT_NE(html.find("(v2.x)"), std::string::npos) << "x1.x is the candidate's third vertex";

  // The pytest snippet calls the kernel on its own order and expects its own order, exactly.
  const CaseOutcome* worst = worst_failing(report);
  ASSERT_NE(worst, nullptr);
  const Expected& e = report.expected[static_cast<std::size_t>(worst - report.outcomes.data())];
  const std::string code = snippet(html);
  const std::array<double, 12> x = candidate_order(e.input.x, stencil);
  EXPECT_EQ(numbers_after(code, "X = np.array("), std::vector<double>(x.begin(), x.end()));
  std::vector<double> grad;
  for (int j = 0; j < 4; ++j)
    for (int c = 0; c < 3; ++c) grad.push_back(e.values.grad[3 * stencil[j] + c]);
  EXPECT_EQ(numbers_after(code, "\"grad\": np.array("), grad);
}

}  // namespace
}  // namespace hinge::conformance
