// The committed conformance sets compiled into hinge::conformance (hinge/conformance/sets.hpp): they are the
// committed files (read here independently, with nlohmann::json), in category order, the deep sets adding
// their hard-family hinges to the quick ones; the float32 sets hold normal floats; each set loads within the
// kit's time budget (the load times are printed).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "hinge/conformance/sets.hpp"

namespace hinge::conformance {
namespace {

namespace fs = std::filesystem;

// The committed file's cases, read with another JSON parser.
std::vector<nlohmann::json> committed(const std::string& relative) {
  std::vector<nlohmann::json> lines;
  std::ifstream in(fs::path(HINGE_CONFORMANCE_DIR) / relative);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

template <std::size_t N>
void expect_equal(const nlohmann::json& want, const std::array<double, N>& got, const std::string& what) {
  ASSERT_EQ(want.size(), N) << what;
  for (std::size_t i = 0; i < N; ++i) EXPECT_EQ(want[i].get<double>(), got[i]) << what << "[" << i << "]";
}

// Every case of the set equals the committed line it came from, bit for bit, in the set's category order.
void expect_committed(Dtype dtype, Depth depth) {
  const std::vector<Expected>& set = conformance_set(dtype, depth);
  const std::string quick_dir = dtype == Dtype::float32 ? "hinges-float32/" : "hinges/",
                    deep_dir = dtype == Dtype::float32 ? "deep-float32/" : "deep/";
  std::size_t k = 0;
  for (const std::string& category : set_categories(dtype, depth)) {
    std::vector<nlohmann::json> lines = committed(quick_dir + category + ".jsonl");
    if (depth == Depth::deep) {
      const std::vector<nlohmann::json> deep = committed(deep_dir + category + ".jsonl");
      lines.insert(lines.end(), deep.begin(), deep.end());
    }
    EXPECT_FALSE(lines.empty()) << category;
    for (const nlohmann::json& line : lines) {
      ASSERT_LT(k, set.size());
      const Expected& e = set[k++];
      const std::string id = line["id"];
      EXPECT_EQ(e.input.id, id);
      EXPECT_EQ(e.input.category, category) << id;
      expect_equal(line["x"], e.input.x, id + " x");
      EXPECT_EQ(line["theta"].get<double>(), e.values.theta) << id;
      expect_equal(line["grad"], e.values.grad, id + " grad");
      expect_equal(line["hess"], e.values.hess, id + " hess");
      EXPECT_EQ(line["length"].get<double>(), e.conditioning.length) << id;
      expect_equal(line["scale"], e.conditioning.scale, id + " scale");
      expect_equal(line["kappa"], e.conditioning.kappa, id + " kappa");
      EXPECT_EQ(line["bits"].get<unsigned>(), e.values.bits) << id;
    }
  }
  EXPECT_EQ(k, set.size());
}

TEST(ConformanceSets, AreTheCommittedFilesInCategoryOrder) {
  for (Dtype dtype : {Dtype::float64, Dtype::float32})
    for (Depth depth : {Depth::quick, Depth::deep}) {
      SCOPED_TRACE(std::string(dtype_name(dtype)) + " " + depth_name(depth));
      expect_committed(dtype, depth);
    }
}

TEST(ConformanceSets, QuickHasTheNineCategoriesAndDeepAddsAtLeast1000HardHinges) {
  for (Dtype dtype : {Dtype::float64, Dtype::float32}) {
    EXPECT_EQ(set_categories(dtype, Depth::quick), categories());
    std::vector<std::string> deep_categories = categories();
    deep_categories.push_back("folded");
    deep_categories.push_back("combined");
    EXPECT_EQ(set_categories(dtype, Depth::deep), deep_categories);
    const auto& quick = conformance_set(dtype, Depth::quick);
    const auto& deep = conformance_set(dtype, Depth::deep);
    EXPECT_GE(quick.size(), 300u) << dtype_name(dtype);
    EXPECT_GE(deep.size(), quick.size() + 1000) << dtype_name(dtype);
    std::map<std::string, int> per_category;
    std::set<std::string> ids;
    for (const Expected& e : deep) {
      ++per_category[e.input.category];
      EXPECT_TRUE(ids.insert(e.input.id).second) << "duplicate id " << e.input.id;
    }
    for (const std::string& c : deep_categories) EXPECT_GT(per_category[c], 0) << c;
    std::printf("%s:", dtype_name(dtype));
    for (const std::string& c : deep_categories) std::printf(" %s %d", c.c_str(), per_category[c]);
    std::printf("\n");
  }
}

bool normal_float_or_zero(double v) {
  return v == 0 || (static_cast<double>(static_cast<float>(v)) == v && std::fabs(v) >= 0x1p-126 &&
                    std::fabs(v) <= 0x1.fffffep127);
}

TEST(ConformanceSets, Float32SetsHoldNormalFloats) {
  for (Depth depth : {Depth::quick, Depth::deep})
    for (const Expected& e : conformance_set(Dtype::float32, depth)) {
      for (double v : e.input.x) EXPECT_TRUE(normal_float_or_zero(v)) << e.input.id << " x " << v;
      EXPECT_TRUE(normal_float_or_zero(e.values.theta)) << e.input.id;
      for (double v : e.values.grad) EXPECT_TRUE(normal_float_or_zero(v)) << e.input.id << " grad " << v;
      for (double v : e.values.hess) EXPECT_TRUE(normal_float_or_zero(v)) << e.input.id << " hess " << v;
    }
}

TEST(ConformanceSets, LoadWithinTheKitsTimeBudget) {
  // The kit's own time: under 1 s for a quick run, 10 s for a deep one; loading a set is a small part of
  // it (measured: milliseconds). The first call parses, later calls return the same set.
  for (Dtype dtype : {Dtype::float64, Dtype::float32})
    for (Depth depth : {Depth::quick, Depth::deep}) {
      const auto start = std::chrono::steady_clock::now();
      const std::vector<Expected>& set = conformance_set(dtype, depth);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::printf("%s %s: %zu cases loaded in %.1f ms\n", dtype_name(dtype), depth_name(depth), set.size(),
                  1e3 * seconds);
      EXPECT_LT(seconds, depth == Depth::quick ? 0.25 : 1.0);
      EXPECT_EQ(&set, &conformance_set(dtype, depth));
    }
}

TEST(ConformanceSets, UnknownDepthIsAnInvalidArgument) {
  EXPECT_EQ(parse_depth("deep"), Depth::deep);
  EXPECT_EQ(parse_depth("quick"), Depth::quick);
  EXPECT_THROW(parse_depth("shallow"), std::invalid_argument);
}

}  // namespace
}  // namespace hinge::conformance
