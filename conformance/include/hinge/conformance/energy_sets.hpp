// hinge/conformance/energy_sets.hpp: the graded cases of the conformance of bending energies
// (docs/energy-conformance.md) and their expectations: the pairs (X, R) of energy_inputs.hpp that an energy
// can grade, the certified psi, gradient and Hessian computed at run time (the oracle's fast path where the
// weight is the contract's), the condition numbers committed (energies/<energy>.jsonl, compiled in: the
// 24-coordinate differences cost about 15 ms a case), and the weights simulators use.
#pragma once

#include <string>
#include <vector>

#include "hinge/conformance/energy_expected.hpp"
#include "hinge/conformance/sets.hpp"

namespace hinge::conformance {

// The deformed hinges per conformance category behind the quick energy set (energy_inputs(per_category)).
inline constexpr int energy_per_category = 10;
// ... and per hard family behind the deep set's additional pairs (deep_energy_inputs): their conditioning is
// computed at run time (about 15 ms a pair), not committed.
inline constexpr int energy_per_family_deep = 20;

// The graded pairs of an energy, in report order, and those left out: |theta - theta_bar| > pi, or an
// infinite energy (tan with theta or theta_bar at +-pi), each "<id>: <why>". Built once per energy and depth
// (thread-safe). Depth::deep adds the hard families' pairs (deep_energy_inputs) to the quick ones.
struct EnergySet {
  std::vector<EnergyCase> cases;
  std::vector<std::string> left_out;
  Depth depth = Depth::quick;
  Dtype dtype = Dtype::float64;
};
// Dtype::float32: the float32 pairs (float32_energy_inputs: every coordinate a normal float), those whose
// outputs (k = 1, the contract's weight) leave float's normal range left out; quick depth only.
const EnergySet& energy_set(Model model, Depth depth = Depth::quick, Dtype dtype = Dtype::float64);
// The quadratic energy's pairs: each deformed hinge of energy_set's with its flat rest hinge (DEFORMED/flat),
// and that rest hinge at rest (DEFORMED/at-rest: X = R, flat); nothing is left out (theta_bar = 0).
const EnergySet& quadratic_set(Depth depth = Depth::quick, Dtype dtype = Dtype::float64);
// The set of `problem`'s energy.
const EnergySet& energy_set_of(const EnergyProblem& problem, Depth depth = Depth::quick, Dtype dtype = Dtype::float64);
// The committed conditioning file of an energy in a dtype: "energies/tan.jsonl", "energies-float32/tan.jsonl".
std::string energy_conditioning_file(const std::string& energy, Dtype dtype);

// The weights a simulator's bending term may use in place of the contract's (docs/energy-conformance.md,
// "Weights", with their sources): "contract" (3 |e_bar|^2 / A_bar, Grinspun et al. 2003), "bridson"
// (|e_bar|^2 / (|N1_bar| + |N2_bar|) = |e_bar|^2 / (2 A_bar), Bridson et al. 2003), "edge-length" (|e_bar|),
// "unit" (1: position-based dihedral constraints, Mueller et al. 2007). Computed in double from R.
const std::vector<std::string>& weight_names();

double named_weight(const std::string& name, const std::array<double, 12>& rest);  // invalid_argument if unknown

// The expectations of `set`'s cases for `problem` (psi in the theta slot, the rest hinge in input.rest),
// each output the double nearest the exact value of k w f, with the committed conditioning (k = 1 and the contract's
// weight; the scales multiplied by k w / a). `weights`: one w per case (empty: the contract's). `diagonal_blocks`: the
// Hessian's off-diagonal 3 x 3 blocks set to zero and kappa_hess taken relative to the diagonal blocks
// (blocks="diagonal"). Throws std::logic_error if a compiled-in conditioning file does not list a case;
// std::invalid_argument for Dtype::float32 (the energy cases are not float32 numbers: a float32 energy set is not
// offered yet).
std::vector<Expected> energy_expectations(const EnergySet& set, const EnergyProblem& problem,
                                          const std::vector<double>& weights, Dtype dtype, bool diagonal_blocks);

// Hessian entries (row-major 12 x 12) outside the four diagonal 3 x 3 blocks set to zero.
void keep_diagonal_blocks(double* hess);

}  // namespace hinge::conformance
