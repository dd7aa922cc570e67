// hinge::study's inputs and the study.json it writes (the study itself, timed and measured end to end, is
// tests/tools/test_study.py): the user's hinges grouped by category, a reproducible sample, the built-in
// hinges, and the shared fit of the paper's Table 2.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "hinge/conformance/inputs.hpp"
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

}  // namespace
}  // namespace hinge::study
