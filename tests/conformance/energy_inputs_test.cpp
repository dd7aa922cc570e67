// The inputs of the conformance of bending energies (hinge/conformance/energy_inputs.hpp): each rest kind
// is what it claims, judged on the certified angles (flat and rest-angle exactly, by the oracle's exact
// stage); every category is there; the rest hinges vary in edge length, area and altitude; the same
// inputs every time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "hinge/conformance/energy_inputs.hpp"
#include "hinge/conformance/inputs.hpp"
#include "hinge/oracle/exact.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {
namespace {

constexpr double pi = std::numbers::pi;

const EnergyInputs& generated() {
  static const EnergyInputs e = energy_inputs(10);
  return e;
}

std::string kind_of(const EnergyCase& c) { return c.category.substr(c.category.find('/') + 1); }

double theta(const std::array<double, 12>& x) { return oracle::certified_theta_derivatives(x).theta; }

double edge_length(const std::array<double, 12>& x) {
  double s = 0;
  for (int c = 0; c < 3; ++c) s += (x[6 + c] - x[3 + c]) * (x[6 + c] - x[3 + c]);
  return std::sqrt(s);
}

TEST(EnergyInputs, EveryDeformedCategoryMeetsEveryRestKindWithUniqueIds) {
  std::set<std::string> categories, ids;
  for (const EnergyCase& c : generated().cases) {
    categories.insert(c.category);
    EXPECT_TRUE(ids.insert(c.id).second) << c.id;
    EXPECT_EQ(c.id.rfind(c.category + "/", 0), 0u) << c.id;
  }
  EXPECT_EQ(categories.size(), conformance::categories().size() * rest_kinds().size());
  EXPECT_GE(generated().cases.size(), 400u);
}

TEST(EnergyInputs, EachRestKindHasTheRestAngleItClaims) {
  for (const EnergyCase& c : generated().cases) {
    const std::string kind = kind_of(c);
    const double theta_bar = theta(c.rest);
    if (kind == "flat") {
      EXPECT_EQ(theta_bar, 0.0) << c.id;  // exactly: the certified angle of a flat hinge is 0
    }
    if (kind == "obtuse") {
      EXPECT_GT(std::fabs(theta_bar), pi / 2) << c.id;
    }
    if (kind == "negative") {
      EXPECT_LT(theta_bar, 0.0) << c.id;
    }
    if (kind == "near-cut") {
      EXPECT_GT(std::fabs(theta_bar), pi - 0.05 - 1e-12) << c.id;  // the construction's angle, rounded by placing
      EXPECT_LE(std::fabs(theta_bar), pi - 1e-3 + 1e-12) << c.id;
    }
  }
}

TEST(EnergyInputs, AtRestTheRestHingeIsTheDeformedOne) {
  for (const EnergyCase& c : generated().cases)
    if (kind_of(c) == "at-rest") {
      EXPECT_EQ(c.rest, c.x) << c.id;
    }
}

TEST(EnergyInputs, AtTheRestAngleThetaEqualsThetaBarExactlyWithAnotherShape) {
  int sheared = 0;
  for (const EnergyCase& c : generated().cases) {
    if (kind_of(c) != "rest-angle") continue;
    EXPECT_TRUE(oracle::same_angle(oracle::exact_hinge(c.x, false), oracle::exact_hinge(c.rest, false))) << c.id;
    EXPECT_EQ(theta(c.x), theta(c.rest)) << c.id;
    EXPECT_NE(edge_length(c.x), edge_length(c.rest)) << c.id;  // scaled by a power of two
    // Beyond a similarity: x0 (or x3) moved along the hinge edge changes its distance to x1 relative to |e0|.
    const auto apex_ratio = [](const std::array<double, 12>& x, int v) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += (x[3 * v + k] - x[3 + k]) * (x[3 * v + k] - x[3 + k]);
      return std::sqrt(s) / edge_length(x);
    };
    const bool similar = std::fabs(apex_ratio(c.x, 0) / apex_ratio(c.rest, 0) - 1) < 1e-12 &&
                         std::fabs(apex_ratio(c.x, 3) / apex_ratio(c.rest, 3) - 1) < 1e-12;
    if (!similar) ++sheared;
  }
  EXPECT_GT(sheared, 0);  // some constructions moved a vertex exactly, not only scaled and turned
}

TEST(EnergyInputs, RestHingesVaryInEdgeLength) {
  std::vector<double> lengths;
  for (const EnergyCase& c : generated().cases)
    if (kind_of(c) == "flat" || kind_of(c) == "obtuse") lengths.push_back(edge_length(c.rest));
  const auto [lo, hi] = std::minmax_element(lengths.begin(), lengths.end());
  EXPECT_GT(*hi / *lo, 4.0);  // |e_bar| drawn in [0.25, 4]
}

TEST(EnergyInputs, PairsMoreThanPiApartAreLeftOutAndListed) {
  for (const EnergyCase& c : generated().cases) EXPECT_LE(std::fabs(theta(c.x) - theta(c.rest)), pi) << c.id;
  EXPECT_FALSE(generated().left_out.empty());  // near-cut rests of the other sign meet near-folded hinges
}

TEST(EnergyInputs, AreTheSameEveryTime) {
  const EnergyInputs again = energy_inputs(10);
  ASSERT_EQ(again.cases.size(), generated().cases.size());
  for (std::size_t i = 0; i < again.cases.size(); ++i) {
    EXPECT_EQ(again.cases[i].id, generated().cases[i].id);
    EXPECT_EQ(again.cases[i].x, generated().cases[i].x);
    EXPECT_EQ(again.cases[i].rest, generated().cases[i].rest);
  }
}

}  // namespace
}  // namespace hinge::conformance
