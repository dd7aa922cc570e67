// The bending problem's one range per parameter and its sentences (hinge/core/bending_problem.hpp): every
// route says the same sentence with its own name for the parameter (the routes themselves:
// tests/tools/test_parameters.py).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "hinge/core/bending_problem.hpp"
#include "hinge/core/samples.hpp"

namespace hinge {
namespace {

// The message of the ParameterError `f` throws ("" if it throws none).
template <class F>
std::string message(F&& f) {
  try {
    f();
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "";
}

constexpr double inf = std::numeric_limits<double>::infinity();

TEST(BendingProblem, EachRangeIsTheContractsAndItsEndsAreWhereItSays) {
  EXPECT_EQ(check_k({0, "--k"}), 0);                  // k >= 0
  EXPECT_EQ(check_poisson({0.5, "--poisson"}), 0.5);  // nu in (-1, 0.5]
  EXPECT_EQ(check_poisson({-0.999, "--poisson"}), -0.999);
  EXPECT_EQ(message([] {
              check_poisson({-1, "--poisson"});
            }),
            "--poisson: Poisson's ratio nu must be in (-1, 0.5], got -1");
  EXPECT_EQ(message([] {
              check_poisson({std::nextafter(0.5, 1.0), "nu"});
            }),
            "nu: Poisson's ratio nu must be in (-1, 0.5], got 0.5000000000000001");
  EXPECT_EQ(message([] { check_k({-1, "--k"}); }), "--k: the bending stiffness k must be finite and >= 0, got -1");
  EXPECT_EQ(message([] { check_young({0, "--young"}); }), "--young: Young's modulus Y must be finite and > 0, got 0");
  EXPECT_EQ(message([] { check_thickness({-0.1, "h"}); }), "h: the thickness h must be finite and > 0, got -0.1");
}

TEST(BendingProblem, NonFiniteValuesAreOutOfEveryRange) {
  for (const double v : {inf, -inf, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_NE(message([&] { check_k({v, "k"}); }), "");
    EXPECT_NE(message([&] { check_young({v, "Y"}); }), "");
    EXPECT_NE(message([&] { check_poisson({v, "nu"}); }), "");
    EXPECT_NE(message([&] { check_thickness({v, "h"}); }), "");
  }
}

TEST(BendingProblem, TheSentenceDiffersOnlyInTheParametersName) {
  const std::string cli = message([] { check_poisson({0.7, "--poisson"}); });
  const std::string python = message([] { check_poisson({0.7, "poisson="}); });
  const std::string scene = message([] { check_poisson({0.7, "material.poisson"}); });
  EXPECT_EQ(cli.substr(std::string("--poisson").size()), python.substr(std::string("poisson=").size()));
  EXPECT_EQ(cli.substr(std::string("--poisson").size()), scene.substr(std::string("material.poisson").size()));
}

TEST(BendingProblem, StiffnessFromTheMaterialIsEquationEleven) {
  const double k = stiffness_from_material({2e6, "Y"}, {0.3, "nu"}, {5e-4, "h"});
  EXPECT_EQ(k, bending_stiffness(2e6, 0.3, 5e-4));  // the same expression, the same bits
  EXPECT_EQ(message([] {
              stiffness_from_material({1e300, "--young"}, {0, "--poisson"}, {1e10, "--thickness"});
            }),
            "--young, --poisson, --thickness: k = Y h^3 / (24 (1 - nu^2)) (eq. (11)) overflows double");
}

TEST(BendingProblem, CommandsTakeTheEvaluatedEnergiesAndRefuseTheOthersWithAReason) {
  EXPECT_EQ(parse_bending_energy("tan", "--energy"), Model::tan);
  EXPECT_EQ(parse_bending_energy("bridson", "--energy"), Model::bridson);
  EXPECT_EQ(message([] { parse_bending_energy("viscoelastic", "--energy"); }),
            "--energy: the viscoelastic energy is library-only: it needs a previous state and a time step");
  EXPECT_EQ(message([] { parse_bending_energy("quadratic", "energy="); }),
            "energy=: the quadratic energy is conformance-only: hinge has no evaluator for it");
  EXPECT_EQ(message([] { parse_bending_energy("springs", "effects.bending.energy"); }),
            "effects.bending.energy: unknown energy 'springs' (expected one of shells, tan, willmore, bridson)");
}

TEST(BendingProblem, TheConformanceOfEnergiesAlsoTakesQuadraticAndCustom) {
  EXPECT_EQ(parse_graded_energy("quadratic", "energy"), Energy::quadratic);
  EXPECT_EQ(parse_graded_energy("custom", "energy"), Energy::custom);
  EXPECT_FALSE(evaluator_model(Energy::custom));
  EXPECT_EQ(evaluator_model(Energy::willmore), Model::willmore);
  EXPECT_NE(message([] { parse_graded_energy("viscoelastic", "energy"); }), "");
}

TEST(BendingProblem, AMeshWithoutAnInteriorEdgeIsRefusedUnlessAllowed) {
  Mesh one;
  one.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  one.faces = {{0, 1, 2}};
  const Topology t = build_topology(one);
  try {
    check_bending_mesh(t, one, nullptr, {"a.obj", "", "--allow-no-hinges", false});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "a.obj: the mesh has no interior edge, so its bending energy is 0 whatever its shape (--allow-no-hinges "
              "if that is meant)");
  }
  EXPECT_NO_THROW(check_bending_mesh(t, one, nullptr, {"a.obj", "", "--allow-no-hinges", true}));
}

TEST(BendingProblem, ADegenerateRestFaceIsNamedWithTheRestFile) {
  Mesh deformed;
  deformed.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  deformed.faces = grid_faces(2, 2);
  Mesh rest = deformed;
  rest.vertices[3] = rest.vertices[0];  // faces (0, 1, 3) and (0, 3, 2) collapse: two vertices coincide
  const Topology t = build_topology(deformed);
  try {
    check_bending_mesh(t, deformed, &rest, {"d.obj", "r.obj", "", false});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("r.obj: face ", 0), 0u) << e.what();
  }
}

TEST(BendingProblem, ZeroThreadsMeansAllCoresAndTheRangeIsChecked) {
  EXPECT_GE(resolve_threads(0, "--threads"), 1);
  EXPECT_EQ(resolve_threads(3, "--threads"), 3);
  EXPECT_EQ(message([] { resolve_threads(-2, "threads="); }),
            "threads=: threads must be in [0, 4096] (0: all cores), got -2");
}

}  // namespace
}  // namespace hinge
