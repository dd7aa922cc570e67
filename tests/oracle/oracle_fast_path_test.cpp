// The oracle's fast path (oracle/src/fast_path.cpp, mesh_fast_path.cpp, proofs/oracle-fast-path.md): it
// gives the doubles of the exact stage and the enclosures, bit for bit (for one hinge and for a mesh), on every
// conformance input, on the hard families and on the committed worked examples; it decides almost every well-shaped
// hinge alone; and what it cannot decide (exact zeros, the branch cut, degenerate hinges) goes on to the stages that
// can.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <numbers>
#include <string>

#include "hinge/conformance/inputs.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/core/samples.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge/reference/evaluate.hpp"
#include "support/same_results.hpp"

namespace hinge::oracle {
namespace {

using X12 = std::array<double, 12>;

Options without_fast_path() {
  Options o;
  o.fast_path = false;
  return o;
}

// Per category, how many hinges each path ended on (printed: oracle/README.md quotes these tables).
struct Tally {
  std::map<std::string, std::array<int, 3>> count;
  void add(const std::string& category, Path p) { ++count[category][static_cast<int>(p)]; }
  void print(const char* title) const {
    std::printf("%s\n%-20s %6s %6s %9s\n", title, "category", "fast", "exact", "interval");
    for (const auto& [category, n] : count) std::printf("%-20s %6d %6d %9d\n", category.c_str(), n[0], n[1], n[2]);
  }
};

TEST(OracleFastPath, GivesTheIntervalPathsDoublesOnEveryConformanceInput) {
  Tally tally;
  for (const auto& c : conformance::inputs()) {
    const CertifiedTheta with = certified_theta_derivatives(c.x),
                         without = certified_theta_derivatives(c.x, without_fast_path());
    EXPECT_EQ("", test::first_difference(with, without)) << c.id;
    tally.add(c.category, with.path);
  }
  tally.print("paths of the conformance inputs:");
  EXPECT_GT(tally.count["well-shaped"][0], 0);
}

TEST(OracleFastPath, GivesTheIntervalPathsDoublesOnTheHardFamilies) {
  // Needles, short hinge edges, near-flat, near-folded, exactly folded and flat, offsets to 1e16, scales
  // 2^-500 to 2^500, combined (conformance.hpp): where the fast path's bounds are weakest.
  Tally tally;
  for (const auto& c : conformance::hard_cases(20261204, 100)) {
    CertifiedTheta with, without;
    try {
      without = certified_theta_derivatives(c.x, without_fast_path());
    } catch (const std::exception& e) {
      EXPECT_ANY_THROW(certified_theta_derivatives(c.x)) << c.id << ": " << e.what();  // the same verdict
      continue;
    }
    with = certified_theta_derivatives(c.x);
    EXPECT_EQ("", test::first_difference(with, without)) << c.id;
    tally.add(c.id.substr(0, c.id.find('/')), with.path);
  }
  tally.print("paths of the hard families (100 draws each, seed 20261204):");
}

TEST(OracleFastPath, DecidesAlmostEveryWellShapedHingeAlone) {
  // On a well-shaped hinge every bound is a few thousand units of 2^-106 of its output, so an output is left
  // open only within about 2^-90 of a midpoint between doubles: about 157 * 2^-37 of hinges. Asked: 99.5%
  // (measured: every one of 2000 here, and of 40000 random hinges in [-1, 1]^12).
  const auto hinges = reference::well_shaped_hinges(2000, 11);
  int fast = 0;
  for (const auto& x : hinges) fast += certified_theta_derivatives(x).path == Path::fast;
  EXPECT_GE(fast, 1990);
}

TEST(OracleFastPath, DecidesZerosOfExactArithmeticItself) {
  // Dyadic coordinates: every product is exact, so the exact zeros of the gradient and Hessian, Y = 0 of a
  // flat or folded hinge, come out with error bound 0 and are decided without the exact stage.
  const X12 axis{0, 1, 0, 0, 0, 0, 1, 0, 0, 0.25, -1, 0.5};
  const X12 folded{0, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, 1, 0};  // theta = +pi, the branch cut (docs/contract.md)
  for (const X12& x : {axis, folded}) {
    const CertifiedTheta a = certified_theta_derivatives(x);
    EXPECT_EQ(a.path, Path::fast);
    EXPECT_EQ("", test::first_difference(a, certified_theta_derivatives(x, without_fast_path())));
  }
  EXPECT_EQ(certified_theta_derivatives(folded).theta, std::numbers::pi);
}

TEST(OracleFastPath, LeavesZerosByCancellationToTheExactStage) {
  // Flat and folded in the plane z = x (exactly: z copies x), with coordinates whose products round: Y = 0
  // only by cancellation, so theta (0 or +pi) is decided in integers (and outputs that nearly cancel, by
  // enclosures).
  const X12 flat{0.1, 0.7, 0.1, 0.3, 0.2, 0.3, 0.9, 0.35, 0.9, 0.6, -0.5, 0.6};
  const X12 folded{0.1, 0.7, 0.1, 0.3, 0.2, 0.3, 0.9, 0.35, 0.9, 0.5, 0.8, 0.5};
  for (const X12& x : {flat, folded}) {
    const CertifiedTheta a = certified_theta_derivatives(x);
    EXPECT_NE(a.path, Path::fast);
    EXPECT_EQ("", test::first_difference(a, certified_theta_derivatives(x, without_fast_path())));
  }
  EXPECT_EQ(certified_theta_derivatives(flat).theta, 0.0);
  EXPECT_EQ(certified_theta_derivatives(folded).theta, std::numbers::pi);
}

TEST(OracleFastPath, LeavesDegenerateAndNonFiniteHingesToTheExactStagesErrors) {
  const X12 zero_area{0, 0, 0, 0, 0, 0, 1, 0, 0, 0.5, -1, 0.25};  // x0 = x1
  EXPECT_THROW(certified_theta_derivatives(zero_area), InputError);
  X12 nan{0, 1, 0, 0, 0, 0, 1, 0, 0, 0.25, -1, 0.5};
  nan[4] = std::nan("");
  EXPECT_THROW(certified_theta_derivatives(nan), InputError);
}

TEST(OracleFastPath, MeshFastPathGivesTheEnclosuresDoubles) {
  struct Case {
    std::string name;
    Mesh deformed, rest;
  };
  std::vector<Case> cases;
  for (const auto& m : conformance::meshes()) cases.push_back({m.name, m.deformed, m.rest});
  cases.push_back({"cloth 11^2", cloth(11, 2), cloth(11, 1)});
  int fast = 0;
  for (const Case& m : cases) {
    const Topology t = build_topology(m.deformed);
    for (Model model : {Model::shells, Model::tan, Model::viscoelastic, Model::willmore}) {
      EnergyParameters p;
      p.model = model;
      p.k = 0.75;
      p.k_d_over_dt = 0.125;
      const CertifiedMesh with = certified_mesh(m.deformed, m.rest, t, p);
      const CertifiedMesh without = certified_mesh(m.deformed, m.rest, t, p, want_all, without_fast_path());
      EXPECT_EQ("", test::first_difference(with, without)) << m.name << " " << model_name(model);
      EXPECT_GT(without.bits, 0u);
      fast += with.bits == 0;
      if (model == Model::willmore) {
        EXPECT_GT(with.bits, 0u);  // sines: not in the fast path
      }
    }
  }
  std::printf("mesh fast path: %d of %zu meshes and energies decided alone\n", fast, 4 * cases.size());
  EXPECT_GE(fast, 3);  // the cloth's three energies at least
}

TEST(OracleFastPath, MeshAtRestIsDecidedWithTheExactTestOfEqualAngles) {
  // theta == theta_bar on every hinge, which the bounds cannot see: decided in integers hinge by hinge,
  // so psi' is exactly zero, and the energy and gradient with it.
  const Mesh m = cloth(11, 2);
  const Topology t = build_topology(m);
  for (Model model : {Model::shells, Model::tan}) {
    EnergyParameters p;
    p.model = model;
    const CertifiedMesh c = certified_mesh(m, m, t, p);
    EXPECT_EQ(c.bits, 0u);
    EXPECT_EQ(c.rounded.energy, 0.0);
    for (double g : c.rounded.gradient) EXPECT_EQ(g, 0.0);
    EXPECT_EQ("", test::first_difference(c, certified_mesh(m, m, t, p, want_all, without_fast_path())));
  }
}

TEST(OracleFastPath, ReportsWhatItDidNotRun) {
  const CertifiedTheta c = certified_theta_derivatives(reference::well_shaped_hinges(1, 3)[0]);
  ASSERT_EQ(c.path, Path::fast);
  EXPECT_EQ(c.bits, 0u);
  EXPECT_EQ(c.exact_bits, 0u);
  EXPECT_STREQ(path_name(c.path), "fast");
}

}  // namespace
}  // namespace hinge::oracle
