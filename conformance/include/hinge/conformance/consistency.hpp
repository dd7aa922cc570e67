// hinge/conformance/consistency.hpp: the consistency checks of the conformance of bending energies
// (docs/energy-conformance.md, "Consistency checks"; docs/contract.md, "Conformance of bending energies"). They need no
// expected values, so they run for every candidate, `custom` included: on well-shaped deformed hinges X (each with its
// rest hinge R),
//   - the gradient against Richardson-extrapolated central differences of the candidate's own energy,
//   - the exact Hessian against Richardson-extrapolated central differences of its own gradient (not for a
//     Gauss-Newton or projected Hessian),
//   - the Hessian's symmetry,
//   - the energy unchanged by rigid motions of X (R stays): a translation, quarter turns about x, y and z, and
//     one general rotation; and the gradient turned with the motion, g(QX + t) = Q g(X),
//   - zero net force and zero net torque about the centroid.
// A check fails where its discrepancy exceeds both 8 times the check's error estimate and 2^-20 relative in
// float64 (2^-8 in float32), relative to the output's norm, or to c = k w where that norm is zero.
//
// The hinge, variables in the contract's order x0, x1, x2, x3 (12 coordinates):
//
//            x2
//           /|\   .
//          / | \  .
//        x0  |  x3      hinge edge x1 -> x2; triangles (x0, x1, x2) and (x3, x2, x1)
//          \ | /
//           \|/
//            x1
//
// Use: plan = consistency_plan(base, dtype); evaluate the candidate on every probe (plan.x[p], plan.rest[p]);
// consistency_checks(plan, outputs, c, options).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "hinge/conformance/energy_inputs.hpp"
#include "hinge/conformance/grading.hpp"

namespace hinge::conformance {

// What a candidate returned for one probe (X, R), in the contract's order (x0, x1, x2, x3).
struct EnergyOutputs {
  bool ok = false;  // false: missing, raised, NaN or infinite
  double energy = 0;
  std::array<double, 12> grad{};
  std::array<double, 144> hess{};  // row-major, 12 x 12
};

struct ConsistencyOptions {
  Dtype dtype = Dtype::float64;  // grading.hpp: the unit roundoff u of the estimates, the probes' format
  bool grad_given = true, hess_given = true;
  bool hessian_exact = true;     // false (gauss-newton, projected): no Hessian-vs-gradient-differences check
  bool energy_given = true;      // false: no gradient-vs-energy-differences check, no energy invariance check
  bool diagonal_blocks = false;  // blocks="diagonal": the Hessian's entries outside its four 3 x 3 diagonal blocks
                                 // are not the candidate's (zero): the difference check compares the blocks only
};

// The steps of the difference checks, h = 2^step_exponent(dtype) * 2^floor(log2 L), L the longest edge of X
// (a power of two, so that the probes x +- h, x +- 2h, x +- 4h are exact): see consistency.cpp for why.
int step_exponent(Dtype dtype);  // -12 in float64, -6 in float32

// The base hinges of the checks and the probes a candidate must evaluate (each coordinate representable in
// the dtype).
struct ConsistencyPlan {
  std::vector<EnergyCase> base;                 // energy_inputs.hpp
  std::vector<std::array<double, 12>> x, rest;  // the probes, contract order, index-aligned
  // Bookkeeping read by consistency_checks: per base case, its first probe and its layout
  // (probes_per_case consecutive probes: the base point, then per coordinate j and level k = 0, 1, 2 the
  // points x + 2^k h e_j and x - 2^k h e_j, then one per rigid motion, in rigid_motions() order).
  Dtype dtype = Dtype::float64;
  std::vector<std::size_t> first;  // index of base case i's first probe
  std::vector<double> length;      // L of base case i (longest edge of its X)
  std::vector<double> step;        // h of base case i
  std::vector<std::array<double, 3>>
      translation;  // the translation applied to base case i (a multiple of 2^floor(log2 L))
  // The actual steps of the difference probes, fl(x + s) - x (== s: checked by consistency_plan), per probe
  // (0 for the base point and the rigid motions).
  std::vector<double> actual_step;
};
inline constexpr std::size_t probes_per_case = 1 + 12 * 3 * 2 + 5;

// The plan for `base` (any hinges; the contract takes the well-shaped ones). The base point of case i is its X
// rounded to the dtype, on the grid of multiples of ulp(max |x| + 4h) so that every difference probe is
// exact; R rounded to the dtype (kept equal to the base point where R == X). Throws std::invalid_argument
// where a base hinge has a non-finite coordinate or a zero longest edge.
ConsistencyPlan consistency_plan(const std::vector<EnergyCase>& base, Dtype dtype);

struct ConsistencyCheck {
  // "gradient against differences of the energy", "Hessian against differences of the gradient",
  // "Hessian symmetry", "energy under rigid motion (quarter turn about z)", "gradient turned with the motion
  // (quarter turn about z)", "net force", "net torque"
  std::string check;
  std::string case_id;
  double discrepancy = 0;  // relative: to the output's norm, or to c where that norm is zero
  double estimate = 0;     // the check's error estimate, same normalization
  double threshold = 0;    // max(8 * estimate, 2^-20 in float64 / 2^-8 in float32)
  bool pass = true;
  std::string detail;  // what was compared; "not evaluated: ..." where a probe it needs is not ok
};

// The consistency checks of the candidate's `outputs` (index-aligned with plan.x) on each base case, in
// base-case order, each case's checks in the order above (checks of outputs not given are left out).
// c[i] = k * w of base case i (the normalizer where an output's norm is zero: c for the energy, c / L for the
// gradient, c / L^2 for the Hessian, c for the torque, which is measured relative to L ||g||). An output counts
// as zero where its norm is within its own rounding, 16 u ||J|| ||x|| (J its Jacobian, measured by differences
// of the candidate's outputs): at rest and at the rest angle a candidate's force is that, not exactly 0.
// Throws std::invalid_argument when the sizes do not match the plan, or options.dtype is not plan.dtype.
std::vector<ConsistencyCheck> consistency_checks(const ConsistencyPlan& plan, const std::vector<EnergyOutputs>& outputs,
                                                 const std::vector<double>& c, const ConsistencyOptions& options);

// The relative threshold below which no check fails: 2^-20 in float64, 2^-8 in float32.
double consistency_floor(Dtype dtype);

// Shared with the whole-mesh conformance (any number of vertices n; x and g hold 3n values):
struct NetLoad {
  double force = 0, torque = 0;  // ||sum_v g_v||, ||sum_v (x_v - centroid) x g_v||
};
// Throws std::invalid_argument when the sizes differ or are not a multiple of 3.
NetLoad net_load(std::span<const double> x, std::span<const double> g);

// A rigid motion x -> Q x + t. The quarter turns are signed permutations (exact in any format); the
// translation is dyadic but adding it rounds, and the general rotation's entries are rounded (it is
// orthogonal to within a few u): the checks' estimate 16 (1 + kappa) u covers both (consistency.cpp).
// The translation is in units of the object's size: consistency_plan multiplies it by 2^floor(log2 L).
struct RigidMotion {
  std::string name;
  std::array<double, 9> rotation;  // Q, row-major
  std::array<double, 3> translation;
};
// "translation", "quarter turn about x", "quarter turn about y", "quarter turn about z", "general rotation".
const std::vector<RigidMotion>& rigid_motions();
// Q x_v + t for every vertex v of `x` (3n coordinates); translate = false turns a gradient (Q g_v). Call it
// qualified (conformance::apply) on a std::array: argument-dependent lookup also finds std::apply.
std::vector<double> apply(const RigidMotion& m, std::span<const double> x, bool translate = true);

}  // namespace hinge::conformance
