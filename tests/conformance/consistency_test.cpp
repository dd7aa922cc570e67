// The consistency checks of the energy conformance (hinge/conformance/consistency.hpp): a correct candidate
// (the reference assembled in double, on the hinge's two triangles) passes every check in float64 and in
// float32, for every energy; each check fails on what it is there to catch (a gradient 1% off its own
// energy, a Hessian 1% off in one entry pair, an asymmetric Hessian, an energy that is not rigid-invariant);
// a probe the candidate could not evaluate fails the checks that need it, "not evaluated"; the probes are
// exact in the dtype; net_load measures what it says.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <numeric>

#include "hinge/conformance/consistency.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/reference/assemble.hpp"

namespace hinge::conformance {
namespace {

const std::vector<EnergyCase>& well_shaped() {  // 60 base cases: 12 deformed hinges x 6 rest kinds, less those left out
  static const std::vector<EnergyCase> cases = [] {
    std::vector<EnergyCase> out;
    for (const EnergyCase& c : energy_inputs(12).cases)
      if (c.category.rfind("well-shaped/", 0) == 0) out.push_back(c);
    return out;
  }();
  return cases;
}

// A candidate made from the reference in double: psi, its gradient and exact Hessian of the hinge's two
// triangles, the contract's weight, k = 1. `alter` changes the outputs at a probe (a deliberately wrong
// candidate); with float32 the outputs are rounded to float, as a float32 candidate's are.
using Alteration = std::function<void(const std::array<double, 12>& x, EnergyOutputs&)>;

EnergyOutputs evaluate(Model model, const std::array<double, 12>& x, const std::array<double, 12>& rest, Dtype dtype,
                       const Alteration& alter = {}) {
  EnergyOutputs o;
  try {
    const Mesh deformed = hinge_mesh(x);
    const Topology topology = build_topology(deformed);
    EnergyParameters parameters;
    parameters.model = model;
    const auto coefficients = reference::rest_state<double>(hinge_mesh(rest), topology, parameters);
    const MeshDerivatives<double> d = reference::assemble<double>(deformed, topology, coefficients, model);
    o.energy = d.energy;
    for (int i = 0; i < 12; ++i) o.grad[i] = d.gradient[i];
    const Eigen::MatrixXd h = Eigen::MatrixXd(d.hessian).selfadjointView<Eigen::Upper>();
    for (int r = 0; r < 12; ++r)
      for (int c = 0; c < 12; ++c) o.hess[12 * r + c] = h(r, c);
    o.ok = true;
  } catch (const DomainError&) {  // tan with a folded rest hinge: the candidate raises
    return o;
  }
  if (alter) alter(x, o);
  if (dtype == Dtype::float32) {
    const auto to_float = [](double& v) { v = static_cast<float>(v); };
    to_float(o.energy);
    std::for_each(o.grad.begin(), o.grad.end(), to_float);
    std::for_each(o.hess.begin(), o.hess.end(), to_float);
  }
  for (double v : o.hess) o.ok = o.ok && std::isfinite(v);
  return o;
}

// c = k w = a (k = 1), the contract's weight 3 |e_bar|^2 / A_bar of the rest hinge.
double weight(const std::array<double, 12>& rest) {
  const Mesh m = hinge_mesh(rest);
  EnergyParameters parameters;
  parameters.model = Model::shells;
  return reference::rest_state<double>(m, build_topology(m), parameters)[0].a;
}

struct Evaluated {
  ConsistencyPlan plan;
  std::vector<ConsistencyCheck> checks;
};

Evaluated run(Model model, Dtype dtype, const Alteration& alter = {}, const ConsistencyOptions* given = nullptr,
              const std::vector<EnergyCase>& base = well_shaped()) {
  Evaluated r;
  r.plan = consistency_plan(base, dtype);
  std::vector<EnergyOutputs> outputs;
  outputs.reserve(r.plan.x.size());
  for (std::size_t p = 0; p < r.plan.x.size(); ++p)
    outputs.push_back(evaluate(model, r.plan.x[p], r.plan.rest[p], dtype, alter));
  std::vector<double> c;
  for (std::size_t i = 0; i < r.plan.base.size(); ++i) c.push_back(weight(r.plan.rest[r.plan.first[i]]));
  ConsistencyOptions options;
  if (given) options = *given;
  options.dtype = dtype;
  r.checks = consistency_checks(r.plan, outputs, c, options);
  return r;
}

std::string describe(const ConsistencyCheck& c) {
  std::string s = c.case_id;
  s += ": ";
  s += c.check;
  s += ": discrepancy " + std::to_string(c.discrepancy);
  s += ", estimate " + std::to_string(c.estimate);
  s += ", threshold " + std::to_string(c.threshold);
  s += " (" + c.detail + ")";
  return s;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The models whose candidate is defined on every well-shaped case (tan is infinite at a folded rest hinge:
// those cases are skipped by the candidate raising in rest_state, so the probes are not ok).
bool evaluable(Model model, const EnergyCase& c) { return evaluate(model, c.x, c.rest, Dtype::float64).ok; }

std::vector<EnergyCase> evaluable_cases(Model model) {
  std::vector<EnergyCase> out;
  for (const EnergyCase& c : well_shaped())
    if (evaluable(model, c)) out.push_back(c);
  return out;
}

TEST(Consistency, TheBaseCasesAreTheSixtyWellShapedOnes) {
  EXPECT_EQ(well_shaped().size(), 60u);
  for (Model model : {Model::shells, Model::willmore, Model::bridson})
    EXPECT_EQ(evaluable_cases(model).size(), well_shaped().size()) << model_name(model);
}

TEST(Consistency, ACorrectCandidatePassesEveryCheckInFloat64AndFloat32) {
  for (Dtype dtype : {Dtype::float64, Dtype::float32})
    for (Model model : {Model::shells, Model::tan, Model::willmore, Model::bridson}) {
      const std::vector<EnergyCase> cases = evaluable_cases(model);
      const Evaluated r = run(model, dtype, {}, nullptr, cases);
      // 15 checks per case: gradient, Hessian, symmetry, 5 energies, 5 gradients, net force, net torque.
      EXPECT_EQ(r.checks.size(), 15 * cases.size());
      double worst_margin = 0;  // discrepancy / threshold
      for (const ConsistencyCheck& c : r.checks) {
        EXPECT_TRUE(c.pass) << dtype_name(dtype) << " " << model_name(model) << " " << describe(c);
        EXPECT_TRUE(std::isfinite(c.estimate)) << describe(c);
        worst_margin = std::max(worst_margin, c.discrepancy / c.threshold);
      }
      std::cout << dtype_name(dtype) << " " << model_name(model) << ": " << cases.size()
                << " cases, worst discrepancy / threshold " << worst_margin << "\n";
    }
}

TEST(Consistency, ForACorrectCandidateTheDifferenceEstimatesBoundTheErrorAndStayUnderTheFloatSixtyFourFloor) {
  // The estimate is an estimate, not only a margin: a correct candidate's discrepancy is within it (without
  // the factor 8), in float64 and float32. And the steps keep it under the contract's floor, so that the floor
  // is the threshold: in float64 everywhere, and in float32 for the Hessian. In float32 the gradient's
  // threshold rises above the floor where the energy is large against L ||g|| (tan near its cut and steep
  // near pi, bridson's energy not zero at rest): there u |E| / h is more than 2^-8 ||g||, float32 energies cannot
  // resolve the gradient to 2^-8, and the estimate says so (counted below, not asserted).
  for (Dtype dtype : {Dtype::float64, Dtype::float32})
    for (Model model : {Model::shells, Model::tan, Model::willmore, Model::bridson}) {
      const Evaluated r = run(model, dtype, {}, nullptr, evaluable_cases(model));
      double worst_discrepancy = 0, worst_estimate = 0;
      int above_floor = 0;
      for (const ConsistencyCheck& c : r.checks)
        if (starts_with(c.check, "gradient against") || starts_with(c.check, "Hessian against")) {
          EXPECT_LE(c.discrepancy, c.estimate) << dtype_name(dtype) << " " << model_name(model) << " " << describe(c);
          if (dtype == Dtype::float64 || starts_with(c.check, "Hessian")) {
            EXPECT_EQ(c.threshold, consistency_floor(dtype))
                << dtype_name(dtype) << " " << model_name(model) << " " << describe(c);
          }
          above_floor += c.threshold > consistency_floor(dtype);
          worst_discrepancy = std::max(worst_discrepancy, c.discrepancy);
          worst_estimate = std::max(worst_estimate, c.estimate);
        }
      std::cout << dtype_name(dtype) << " " << model_name(model) << ": worst difference discrepancy "
                << worst_discrepancy << ", estimate " << worst_estimate << " (floor " << consistency_floor(dtype)
                << "), thresholds above the floor: " << above_floor << " of " << 2 * r.plan.base.size() << "\n";
    }
}

TEST(Consistency, AGradientOnePercentOffItsOwnEnergyFailsTheGradientCheck) {
  const Alteration scaled = [](const std::array<double, 12>&, EnergyOutputs& o) {
    for (double& g : o.grad) g *= 1.01;
  };
  for (Dtype dtype : {Dtype::float64, Dtype::float32}) {
    const Evaluated wrong = run(Model::shells, dtype, scaled);
    const Evaluated right = run(Model::shells, dtype);
    int failed = 0, nonzero = 0;
    for (std::size_t i = 0; i < wrong.checks.size(); ++i) {
      const ConsistencyCheck& w = wrong.checks[i];
      if (w.check != "gradient against differences of the energy") continue;
      EXPECT_TRUE(right.checks[i].pass) << describe(right.checks[i]);
      // At rest and at the rest angle the force is zero (to within its rounding): 1% off nothing.
      const bool zero_force =
          w.case_id.find("/at-rest/") != std::string::npos || w.case_id.find("/rest-angle/") != std::string::npos;
      if (!zero_force) {
        ++nonzero;
        failed += !w.pass;
        EXPECT_FALSE(w.pass) << dtype_name(dtype) << " " << describe(w);
      }
    }
    EXPECT_EQ(nonzero, std::count_if(well_shaped().begin(), well_shaped().end(),
                                     [](const EnergyCase& c) {
                                       return c.id.find("/at-rest/") == std::string::npos &&
                                              c.id.find("/rest-angle/") == std::string::npos;
                                     }))
        << dtype_name(dtype);
    EXPECT_EQ(failed, nonzero) << dtype_name(dtype);
  }
}

// The largest off-diagonal entry of a Hessian (row < col).
std::pair<int, int> largest_off_diagonal(const EnergyOutputs& o) {
  std::pair<int, int> at{0, 1};
  for (int r = 0; r < 12; ++r)
    for (int c = r + 1; c < 12; ++c)
      if (std::fabs(o.hess[12 * r + c]) > std::fabs(o.hess[12 * at.first + at.second])) at = {r, c};
  return at;
}

// The relative change of one Hessian entry (pair) that each dtype's floor must see: 1% in float64; 10% in
// float32, whose floor 2^-8 ||H||_F is 0.4% of the whole Hessian, more than 1% of one entry pair can be.
double entry_change(Dtype dtype) { return dtype == Dtype::float64 ? 0.01 : 0.1; }

TEST(Consistency, AHessianOnePercentOffInOneEntryPairFailsTheHessianCheckAndStaysSymmetric) {
  for (Dtype dtype : {Dtype::float64, Dtype::float32}) {
    const double change = entry_change(dtype);
    const Alteration pair = [change](const std::array<double, 12>&, EnergyOutputs& o) {
      const auto [r, c] = largest_off_diagonal(o);
      o.hess[12 * r + c] *= 1 + change;
      o.hess[12 * c + r] *= 1 + change;
    };
    const Evaluated r = run(Model::shells, dtype, pair);
    int hessian_checks = 0;
    for (const ConsistencyCheck& c : r.checks) {
      if (c.check == "Hessian symmetry") {
        EXPECT_TRUE(c.pass) << describe(c);
      }
      if (c.check != "Hessian against differences of the gradient") continue;
      ++hessian_checks;
      EXPECT_FALSE(c.pass) << dtype_name(dtype) << " " << describe(c);
    }
    EXPECT_EQ(hessian_checks, 60);
  }
}

TEST(Consistency, AnAsymmetricHessianFailsTheSymmetryCheck) {
  for (Dtype dtype : {Dtype::float64, Dtype::float32}) {
    const double change = entry_change(dtype);
    // One entry of the largest off-diagonal pair changed, its partner left as it is.
    const Alteration one_side = [change](const std::array<double, 12>&, EnergyOutputs& o) {
      const auto [r, c] = largest_off_diagonal(o);
      o.hess[12 * r + c] *= 1 + change;
    };
    const Evaluated r = run(Model::shells, dtype, one_side);
    int symmetry_checks = 0;
    for (const ConsistencyCheck& c : r.checks)
      if (c.check == "Hessian symmetry") {
        ++symmetry_checks;
        EXPECT_FALSE(c.pass) << dtype_name(dtype) << " " << describe(c);
      }
    EXPECT_EQ(symmetry_checks, 60);
  }
  // An asymmetry of 2^-18 ||H||_F (4 times the float64 floor) in one entry fails in float64.
  const Alteration small = [](const std::array<double, 12>&, EnergyOutputs& o) {
    double n = 0;
    for (double v : o.hess) n += v * v;
    o.hess[12 * 0 + 5] += 0x1p-18 * std::sqrt(n);
  };
  const Evaluated r = run(Model::shells, Dtype::float64, small);
  for (const ConsistencyCheck& c : r.checks)
    if (c.check == "Hessian symmetry") {
      EXPECT_FALSE(c.pass) << describe(c);
    }
}

TEST(Consistency, AnEnergyThatIsNotRigidInvariantFailsInvarianceAndNetForceButNotTheGradientCheck) {
  // psi + 1e-3 x0.x, with its consistent gradient: the differences agree, the invariances do not.
  const Alteration drift = [](const std::array<double, 12>& x, EnergyOutputs& o) {
    o.energy += 1e-3 * x[0];
    o.grad[0] += 1e-3;
  };
  const Evaluated r = run(Model::shells, Dtype::float64, drift);
  int translation = 0, force = 0;
  for (const ConsistencyCheck& c : r.checks) {
    if (c.check == "gradient against differences of the energy") {
      EXPECT_TRUE(c.pass) << describe(c);
    }
    if (c.check == "energy under rigid motion (translation)") {
      ++translation;
      EXPECT_FALSE(c.pass) << describe(c);
    }
    if (c.check == "net force") {
      ++force;
      EXPECT_FALSE(c.pass) << describe(c);
    }
    if (c.check == "energy under rigid motion (quarter turn about x)") {
      EXPECT_TRUE(c.pass) << describe(c);  // it keeps x0.x: this motion cannot see the term
    }
  }
  EXPECT_EQ(translation, 60);
  EXPECT_EQ(force, 60);
}

TEST(Consistency, AProbeNotEvaluatedFailsTheChecksThatNeedItAndOnlyThem) {
  const std::vector<EnergyCase> base(well_shaped().begin(), well_shaped().begin() + 2);
  const ConsistencyPlan plan = consistency_plan(base, Dtype::float64);
  std::vector<EnergyOutputs> outputs;
  for (std::size_t p = 0; p < plan.x.size(); ++p)
    outputs.push_back(evaluate(Model::shells, plan.x[p], plan.rest[p], Dtype::float64));
  const std::vector<double> c{weight(plan.rest[plan.first[0]]), weight(plan.rest[plan.first[1]])};
  // Case 0: the probe x1.y + 2h raised (the 1 + 6 * 4 + 2 = 27th of the case); case 1: the quarter turn about z.
  outputs[plan.first[0] + 1 + 6 * 4 + 2].ok = false;
  outputs[plan.first[1] + probes_per_case - 2].ok = false;
  outputs[plan.first[1] + probes_per_case - 2].energy = std::nan("");
  const std::vector<ConsistencyCheck> checks = consistency_checks(plan, outputs, c, {});
  for (const ConsistencyCheck& k : checks) {
    const bool case0_difference =
        k.case_id == base[0].id && (starts_with(k.check, "gradient against") ||
                                    starts_with(k.check, "Hessian against") || starts_with(k.check, "energy under") ||
                                    starts_with(k.check, "gradient turned") || starts_with(k.check, "net "));
    const bool case1_turn = k.case_id == base[1].id && k.check.find("(quarter turn about z)") != std::string::npos;
    if (case0_difference || case1_turn) {
      EXPECT_FALSE(k.pass) << describe(k);
      EXPECT_EQ(k.discrepancy, std::numeric_limits<double>::infinity()) << describe(k);
      EXPECT_TRUE(starts_with(k.detail, "not evaluated")) << describe(k);
    } else {
      EXPECT_TRUE(k.pass) << describe(k);
    }
  }
  EXPECT_NE(checks[0].detail.find("x1.y + 2h"), std::string::npos) << checks[0].detail;
}

TEST(Consistency, EveryProbeIsExactInItsDtypeWithExactStepsAndTheRestHingeUnmoved) {
  for (Dtype dtype : {Dtype::float64, Dtype::float32}) {
    const ConsistencyPlan plan = consistency_plan(well_shaped(), dtype);
    ASSERT_EQ(plan.x.size(), well_shaped().size() * probes_per_case);
    ASSERT_EQ(plan.rest.size(), plan.x.size());
    for (std::size_t p = 0; p < plan.x.size(); ++p)
      for (int i = 0; i < 12; ++i) {
        if (dtype == Dtype::float32) {
          EXPECT_EQ(plan.x[p][i], static_cast<float>(plan.x[p][i]));
          EXPECT_EQ(plan.rest[p][i], static_cast<float>(plan.rest[p][i]));
        }
      }
    for (std::size_t i = 0; i < plan.base.size(); ++i) {
      const std::size_t first = plan.first[i];
      const double h = plan.step[i];
      EXPECT_EQ(h, std::ldexp(1.0, std::ilogb(plan.length[i]) + step_exponent(dtype)));
      for (std::size_t p = first; p < first + probes_per_case; ++p) {
        EXPECT_EQ(plan.rest[p], plan.rest[first]);  // R stays, for the differences and the motions
      }
      for (int j = 0; j < 12; ++j)
        for (int level = 0; level < 3; ++level) {
          const std::size_t plus = first + 1 + 6 * j + 2 * level;
          EXPECT_EQ(plan.x[plus][j] - plan.x[first][j], std::ldexp(h, level));
          EXPECT_EQ(plan.x[plus + 1][j] - plan.x[first][j], -std::ldexp(h, level));
          EXPECT_EQ(plan.actual_step[plus], std::ldexp(h, level));
        }
      // The base point is X itself to within the grid (one unit of the dtype at 2 (max |x| + 4h)).
      for (int j = 0; j < 12; ++j) {
        EXPECT_LE(std::fabs(plan.x[first][j] - plan.base[i].x[j]), 4 * unit_roundoff(dtype) * (4 + 16 * h))
            << plan.base[i].id;
      }
      // The quarter turns are exact: the turned base point, to the bit.
      for (std::size_t m = 1; m <= 3; ++m) {
        const std::vector<double> turned = conformance::apply(rigid_motions()[m], plan.x[first]);
        const std::array<double, 12>& probe = plan.x[first + 1 + 72 + m];
        EXPECT_TRUE(std::equal(turned.begin(), turned.end(), probe.begin())) << rigid_motions()[m].name;
      }
    }
  }
}

TEST(Consistency, TheRotationsAreRotations) {
  for (const RigidMotion& m : rigid_motions()) {
    const auto& Q = m.rotation;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        double dot = 0;
        for (int k = 0; k < 3; ++k) dot += Q[3 * a + k] * Q[3 * b + k];
        EXPECT_NEAR(dot, a == b ? 1.0 : 0.0, 4 * 0x1p-53) << m.name;  // entries rounded: a few u
      }
    const double det =
        Q[0] * (Q[4] * Q[8] - Q[5] * Q[7]) - Q[1] * (Q[3] * Q[8] - Q[5] * Q[6]) + Q[2] * (Q[3] * Q[7] - Q[4] * Q[6]);
    EXPECT_NEAR(det, 1.0, 8 * 0x1p-53) << m.name;  // proper rotations, not reflections
  }
}

TEST(Consistency, NetLoadOfAForceFieldIsItsResultantAndItsMomentAboutTheCentroid) {
  const std::vector<double> x{0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 2, 1, 1, 1};  // 5 vertices
  // A uniform field: resultant 5 f, no moment about the centroid.
  const std::vector<double> uniform{1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3, 1, 2, 3};
  NetLoad n = net_load(x, uniform);
  EXPECT_DOUBLE_EQ(n.force, 5 * std::sqrt(14.0));
  EXPECT_NEAR(n.torque, 0, 1e-14);
  // A couple: +-e_y at x = 2 e_x and the origin: no resultant, moment 2 about z.
  std::vector<double> couple(15, 0);
  couple[3 + 1] = 1;
  couple[1] = -1;
  n = net_load(x, couple);
  EXPECT_EQ(n.force, 0);
  EXPECT_DOUBLE_EQ(n.torque, 2);
  EXPECT_THROW(net_load(x, std::vector<double>(12)), std::invalid_argument);
}

TEST(Consistency, NetLoadIsUnchangedByMovingTheMeshAndTurningItsGradient) {
  // A correct gradient has (nearly) no net load wherever the hinge is; a gradient with a net load keeps its
  // sizes when the hinge is moved and the gradient turned with it.
  const EnergyCase& c = well_shaped()[7];
  const EnergyOutputs o = evaluate(Model::tan, c.x, c.rest, Dtype::float64);
  ASSERT_TRUE(o.ok);
  const double g = std::sqrt(std::inner_product(o.grad.begin(), o.grad.end(), o.grad.begin(), 0.0));
  std::vector<double> loaded(o.grad.begin(), o.grad.end());
  loaded[0] += g / 4;  // a net force g / 4 along x at x0
  const NetLoad before = net_load(c.x, loaded);
  EXPECT_NEAR(before.force, g / 4, 1e-12 * g);
  for (const RigidMotion& m : rigid_motions()) {
    const std::vector<double> moved = conformance::apply(m, c.x), turned = conformance::apply(m, loaded, false);
    const NetLoad after = net_load(moved, turned);
    EXPECT_NEAR(after.force, before.force, 1e-12 * g) << m.name;
    EXPECT_NEAR(after.torque, before.torque, 1e-12 * g * 8) << m.name;
    const NetLoad correct = net_load(moved, conformance::apply(m, o.grad, false));
    EXPECT_LT(correct.force, 1e-12 * g) << m.name;
    EXPECT_LT(correct.torque, 1e-12 * g * 8) << m.name;
  }
}

TEST(Consistency, PlanAndChecksOfSixtyCasesTakeMilliseconds) {
  const std::vector<EnergyCase>& base = well_shaped();
  const auto start = std::chrono::steady_clock::now();
  const ConsistencyPlan plan = consistency_plan(base, Dtype::float64);
  const auto planned = std::chrono::steady_clock::now();
  std::vector<EnergyOutputs> outputs;
  for (std::size_t p = 0; p < plan.x.size(); ++p)
    outputs.push_back(evaluate(Model::shells, plan.x[p], plan.rest[p], Dtype::float64));
  std::vector<double> c;
  for (std::size_t i = 0; i < base.size(); ++i) c.push_back(weight(plan.rest[plan.first[i]]));
  const auto evaluated = std::chrono::steady_clock::now();
  const std::vector<ConsistencyCheck> checks = consistency_checks(plan, outputs, c, {});
  const auto checked = std::chrono::steady_clock::now();
  const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  std::cout << base.size() << " cases, " << plan.x.size() << " probes, " << checks.size() << " checks: plan "
            << ms(start, planned) << " ms, candidate " << ms(planned, evaluated) << " ms, checks "
            << ms(evaluated, checked) << " ms\n";
  EXPECT_LT(ms(start, planned) + ms(evaluated, checked), 2000);  // generous: a shared, sanitized machine
}

TEST(Consistency, OutputsNotGivenAreNotCheckedAndAnInexactHessianIsNotComparedWithDifferences) {
  const std::vector<EnergyCase> base(well_shaped().begin(), well_shaped().begin() + 6);
  const auto names = [](const Evaluated& r) {
    std::vector<std::string> out;
    for (const ConsistencyCheck& c : r.checks) {
      EXPECT_TRUE(c.pass) << describe(c);
      if (c.case_id == r.plan.base[0].id) out.push_back(c.check);
    }
    return out;
  };
  ConsistencyOptions gauss_newton;
  gauss_newton.hessian_exact = false;
  std::vector<std::string> checks = names(run(Model::shells, Dtype::float64, {}, &gauss_newton, base));
  EXPECT_EQ(checks.size(), 14u);
  EXPECT_EQ(std::count(checks.begin(), checks.end(), "Hessian against differences of the gradient"), 0);
  ConsistencyOptions energy_only;
  energy_only.grad_given = energy_only.hess_given = false;
  checks = names(run(Model::shells, Dtype::float64, {}, &energy_only, base));
  ASSERT_EQ(checks.size(), 5u);
  for (const std::string& c : checks) EXPECT_TRUE(starts_with(c, "energy under rigid motion")) << c;
}

TEST(Consistency, ChecksRejectOutputsThatDoNotMatchThePlan) {
  const ConsistencyPlan plan = consistency_plan({well_shaped()[0]}, Dtype::float64);
  EXPECT_THROW(consistency_checks(plan, std::vector<EnergyOutputs>(3), {1.0}, {}), std::invalid_argument);
  EXPECT_THROW(consistency_checks(plan, std::vector<EnergyOutputs>(plan.x.size()), {}, {}), std::invalid_argument);
  ConsistencyOptions float32;
  float32.dtype = Dtype::float32;
  EXPECT_THROW(consistency_checks(plan, std::vector<EnergyOutputs>(plan.x.size()), {1.0}, float32),
               std::invalid_argument);
}

}  // namespace
}  // namespace hinge::conformance
