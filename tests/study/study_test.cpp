// hinge::study's inputs and the study.json it writes (the study itself, timed and measured end to end, is
// tests/tools/test_study.py): the user's hinges grouped by category, a reproducible sample, the built-in
// hinges, the shared fit of the paper's Table 2; and the rows of contract version 3 on a few hinges: the
// oracle's and the faithful mode's errors and frontier, outside rows from plugins (one crashing).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "hinge/conformance/inputs.hpp"
#include "hinge/conformance/plugin.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/study_json.hpp"
#include "hinge/study/study.hpp"

namespace hinge::study {
namespace {

std::string written(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("hinge-study-test-" + name + ".jsonl");
  std::ofstream(path) << text;
  return path.string();
}

constexpr const char* kHinge = R"("x": [0.1, 1, 0.2, 0, 0, 0, 1, 0, 0, 0.4, 0.1, 1])";

TEST(StudyInputs, AFilesHingesAreGroupedByTheirCategoryOrAsInput) {
  const auto hinges = read_hinges(written("grouped", std::string(R"({"id": "a", "category": "mine", )") + kHinge +
                                                         "}\n\n" + R"({"id": "b", )" + kHinge + "}\n"));
  ASSERT_EQ(hinges.size(), 2u);
  EXPECT_EQ(hinges[0].id, "a");
  EXPECT_EQ(hinges[0].category, "mine");
  EXPECT_EQ(hinges[1].category, "input");
  EXPECT_EQ(hinges[1].x[9], 0.4);
}

TEST(StudyInputs, AnInvalidLineIsAnErrorNamingTheFileAndLine) {
  const std::string path = written("invalid", std::string(R"({"id": "a", )") + kHinge + "}\nnot json\n");
  try {
    read_hinges(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path + ":2: ", 0), 0u) << e.what();
  }
  EXPECT_THROW(read_hinges(written("empty", "\n")), InputError);  // no hinge at all
}

TEST(StudyInputs, ASampleIsReproducibleAndKeepsTheFilesOrder) {
  std::vector<StudyHinge> all;
  for (int i = 0; i < 100; ++i) all.push_back({std::to_string(i), "input", {}});
  const auto a = sample(all, 10), b = sample(all, 10);
  ASSERT_EQ(a.size(), 10u);
  std::set<std::string> distinct;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, b[i].id);
    if (i > 0) {
      EXPECT_LT(std::stoi(a[i - 1].id), std::stoi(a[i].id));
    }
    distinct.insert(a[i].id);
  }
  EXPECT_EQ(distinct.size(), 10u);
  EXPECT_EQ(sample(all, 0).size(), all.size());  // 0: every hinge
}

TEST(StudyInputs, TheQuickStudysHingesAreTheConformanceInputs) {
  const auto builtin = builtin_hinges(true);
  const auto inputs = conformance::inputs();
  ASSERT_EQ(builtin.size(), inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    EXPECT_EQ(builtin[i].id, inputs[i].id);
    EXPECT_EQ(builtin[i].x, inputs[i].x);
  }
}

TEST(StudyJson, RowsAndTheSharedFitAreWrittenWithVersionTwo) {
  Study s;
  s.cpu = "test";
  Row r;
  r.method = "fast";
  r.ns_per_hinge = {100, 150, 200};
  r.error_u["well-shaped"][2].max = 3;
  s.rows.push_back(r);
  s.shared_fit.k = 1.02;
  s.shared_fit.ln_a = {{"fast", -3.5}, {"reference", -2.0}};
  s.shared_fit.fast_ln_a = -3.5, s.shared_fit.has_fast = true;
  std::ostringstream out;
  io::write_study_json(out, s);
  const std::string j = out.str();
  EXPECT_NE(j.find(R"("version": 2)"), std::string::npos);
  EXPECT_NE(j.find(R"("method": "fast")"), std::string::npos);
  EXPECT_NE(j.find(R"("max_bits": 2)"), std::string::npos);  // log2(1 + 3)
  EXPECT_NE(j.find(R"("mesh_shared_k")"), std::string::npos);
  EXPECT_EQ(io::error_bits(0), 0);
}

// Two hinges of each built-in category (18): every category's hard cases in a study of a second or two.
std::vector<StudyHinge> few_hinges() {
  std::vector<StudyHinge> few;
  std::map<std::string, int> taken;
  for (const auto& h : builtin_hinges(true))
    if (taken[h.category]++ < 2) few.push_back(h);
  return few;
}

Options few_rows(std::vector<std::string> methods) {
  Options o;
  o.hinges = few_hinges();
  o.source = "test";
  o.methods = std::move(methods);
  o.scalars = {parse_scalar_type("double")};
  o.mesh = false;
  o.quick = true;
  o.budget_seconds = 0.5;  // errors on all 18 hinges, a few rounds each: the rows' content is asserted, not their times
  return o;
}

const Row& row_of(const Study& s, const std::string& method) {
  for (const Row& r : s.rows)
    if (r.method == method) return r;
  throw std::logic_error("no row " + method);
}

TEST(StudyRows, TheOraclesRowIsExactEverywhereAndOnTheFrontierBesideFastAndTheFaithfulMode) {
  const Study s = run(few_rows({"fast", "faithful", "oracle"}));
  const Row& oracle = row_of(s, "oracle");
  const Row& faithful = row_of(s, "faithful");
  const Row& fast = row_of(s, "fast");
  // The oracle with its fast path gives the same doubles as without it (oracle.hpp): error exactly 0.
  EXPECT_EQ(oracle.worst, 0);
  // Nothing is more accurate than 0: it is on the frontier unless a faster row is exact too (the faithful
  // mode is on some sets of hinges: at equal error the faster row is on the frontier).
  EXPECT_EQ(oracle.on_frontier, !(faithful.worst == 0 && faithful.x_fast[2] < oracle.x_fast[2]));
  // The faithful mode is within 1 unit of every output group (hinge/fast/faithful.hpp: measured on the hard
  // families, which these hinges are drawn from).
  EXPECT_LE(faithful.worst, 1);
  EXPECT_EQ(fast.x_fast, (std::array<double, 3>{1, 1, 1}));  // the row every ratio is to
  for (const Row* r : {&oracle, &faithful, &fast}) {
    EXPECT_GE(r->rounds, 3u) << r->method;  // the budget's floor
    EXPECT_GT(r->x_fast[2], 0) << r->method;
    EXPECT_EQ(r->hinges, s.hinges) << r->method;  // every hinge measured
  }
  // The escalation: a fraction per category, every category there.
  EXPECT_EQ(oracle.escalation.size(), s.categories.size());
  for (const auto& [category, f] : oracle.escalation) {
    EXPECT_GE(f, 0) << category;
    EXPECT_LE(f, 1) << category;
  }
  // The frontier: no row on it is beaten in both time and worst error by another.
  for (const Row& a : s.rows)
    for (const Row& b : s.rows)
      if (a.on_frontier && &a != &b) {
        EXPECT_FALSE(b.x_fast[2] <= a.x_fast[2] && b.worst <= a.worst &&
                     (b.x_fast[2] < a.x_fast[2] || b.worst < a.worst))
            << a.method << " beaten by " << b.method;
      }
}

TEST(StudyRows, APluginIsAnOutsideRowMeasuredLikeOursAndACrashIsItsFailureNotTheStudys) {
  Options o = few_rows({"fast"});
  o.outside.push_back(plugin_candidate(HINGE_CANDIDATE_FAST, "hinge_candidate", "fast-plugin"));
  o.outside.push_back(plugin_candidate(HINGE_CRASHING_CANDIDATE));
  const Study s = run(o);
  const Row& ours = row_of(s, "fast");
  const Row& plugin = row_of(s, "fast-plugin");
  EXPECT_TRUE(plugin.outside);
  EXPECT_FALSE(ours.outside);
  // The same kernel through hinge/candidate.h: the same doubles, so the same errors to the bit.
  ASSERT_EQ(plugin.error_u.size(), ours.error_u.size());
  for (const auto& [category, e] : ours.error_u)
    for (int g = 0; g < 3; ++g) {
      EXPECT_EQ(plugin.error_u.at(category)[g].max, e[g].max) << category << g;
      EXPECT_EQ(plugin.error_u.at(category)[g].median, e[g].median) << category << g;
    }
  EXPECT_GE(plugin.rounds, 3u);
  EXPECT_GT(plugin.x_fast[2], 0);
  EXPECT_EQ(plugin.ns_per_hinge[0], plugin.ns_per_hinge[2]);  // the three times are the one call's
  // The crashing plugin: its label is the file's name, the hinges it crashed on failed, the crash named.
  const Row& crashing = row_of(s, std::filesystem::path(HINGE_CRASHING_CANDIDATE).filename().string());
  EXPECT_GT(crashing.failed, 0u);
  EXPECT_LT(crashing.failed, crashing.hinges);  // and the others measured
  EXPECT_NE(crashing.error.find("crashed (signal 6, SIGABRT)"), std::string::npos) << crashing.error;
  EXPECT_FALSE(crashing.on_frontier);
  // A library that cannot be loaded is an error before any row runs.
  EXPECT_THROW(plugin_candidate("/nonexistent/plugin.so"), conformance::PluginError);
}

TEST(StudyRows, AnUnknownMethodIsNamed) {
  try {
    check_method("frobnicate");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("frobnicate"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("oracle"), std::string::npos);  // the names it knows
  }
  EXPECT_EQ(check_method("faithful"), "faithful");
}

TEST(StudyJson, VersionTwoSaysHowEveryRowWasTimedAndMarksOutsideRows) {
  Study s;
  s.timing = {{"call", "one call per hinge"}};
  Row r;
  r.method = "mine";
  r.outside = true;
  r.escalation["well-shaped"] = 0.25;
  s.rows.push_back(r);
  std::ostringstream out;
  io::write_study_json(out, s);
  const std::string j = out.str();
  EXPECT_NE(j.find(R"("timing": {)"), std::string::npos);
  EXPECT_NE(j.find(R"("call": "one call per hinge")"), std::string::npos);
  EXPECT_NE(j.find(R"("outside": true)"), std::string::npos);
  EXPECT_NE(j.find(R"("well-shaped": 0.25)"), std::string::npos);
  EXPECT_EQ(io::row_label(r), "mine");  // an outside row's label alone
}

}  // namespace
}  // namespace hinge::study
