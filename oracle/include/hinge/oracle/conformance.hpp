// hinge/oracle/conformance.hpp: the conformance kit behind `hinge conform` (docs/contract.md): the
// conformance inputs by category, their certified outputs and condition numbers, the tolerance policy,
// and the comparison of a candidate implementation's outputs. Documented in docs/conformance.md; the
// files in conformance/ follow docs/conformance-format.md (format version below).
//
// Everything here is deterministic: the inputs are built with IEEE-754 basic operations (compiled without
// contraction into fused multiply-adds) and correctly rounded MPFR functions, the outputs are certified,
// and the condition numbers are computed from certified or exact values; the same bits come out on any
// platform, so the committed vectors can be checked by regenerating them.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "hinge/io/eval_output.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::oracle::conformance {

inline constexpr int format_version = 1;

// One hinge of the conformance set: "category/NN-tag".
struct Case {
  std::string id, category;
  std::array<double, 12> x{};
};

// The categories, in report order: well-shaped, rotations, scales, offsets, near-flat, near-folded,
// needles, short-hinge-edges, boundary-meshes.
const std::vector<std::string>& categories();

// The conformance inputs (about 300 hinges), category by category.
std::vector<Case> inputs();

// The hard families (docs/hard-cases.md, ctest label hard): needles (caps and spikes to 1e-15),
// short-hinge-edges (2^-1 to 2^-60 of the other edges), near-flat (|theta| to 1e-15), near-folded (to pi -
// 1e-15), folded (exactly folded or flat, lattice planes, scaled and offset), offsets (to 1e16), scales
// (2^-500 to 2^500), combined (needles offset and scaled): `per_family` random draws of each from
// `seed` (SplitMix64, the same doubles on every platform), invalid draws dropped. Ids "family/N-tag".
const std::vector<std::string>& hard_families();
std::vector<Case> hard_cases(std::uint64_t seed, int per_family);

// The meshes (with boundaries) whose hinges form the category boundary-meshes, and whose energies,
// gradients and Hessians are conformance vectors of their own.
struct MeshCase {
  std::string name;
  Mesh deformed, rest;
};
std::vector<MeshCase> meshes();

// The groups of outputs compared separately: theta, grad (12), hess (144).
inline constexpr std::array<const char*, 3> group_names{"theta", "grad", "hess"};

// Conditioning of one case (docs/conformance.md, "Tolerance policy"). With L the longest of the five
// edge vectors and J_f the Jacobian of output group f with respect to the 12 coordinates
// (J_theta = grad theta, J_grad = Hess theta, J_hess the third derivatives, by central differences on
// the exact form with step 2^-100 L):
//   scale_f = L ||J_f||_F        kappa_f = scale_f / ||f||_2   (kappa_f = 1 where f is exactly zero)
struct Conditioning {
  double length = 0;
  std::array<double, 3> scale{};
  std::array<double, 3> kappa{};
};

struct Expected {
  Case input;
  CertifiedTheta values;
  Conditioning conditioning;
};

// Certified outputs and conditioning of `c`. Throws as certified_theta_derivatives does.
Expected expected(const Case& c);

// The tolerance policy: output group f of a case passes when its normwise error, in units of
// u = 2^-53 relative to ||f||_2 (to scale_f where f is exactly zero), is at most  base + c * kappa_f.
// The constants are calibrated in docs/conformance.md: the reference evaluated in double uses at most
// 0.1 of the tolerance in any category, and an error of 64 ulps in every Hessian entry exceeds it on
// every well-shaped case.
struct Policy {
  double base = 16;  // units of 2^-53 granted to every case: the outputs' own rounding and a stable algorithm's
  double c = 4;      // growth with the conditioning
};

// A candidate's answer for one case: a line of `hinge eval` output (read from a file, or made from a
// plugin's outputs).
using CandidateResult = io::EvalOutput;

// The accuracy a candidate reaches, best first (docs/conformance.md, "Tiers"): every output equal to
// the certified one; every output group within 1 unit of 2^-53 (normwise, as the errors are measured);
// within 4 units; within the tolerance policy; outside it.
enum class Tier { correctly_rounded, faithful, four_units, policy, fail };
// "correctly-rounded", "faithful", "4u", "policy", "fail" (docs/contract.md).
const char* tier_name(Tier t);

struct CaseOutcome {
  std::string id, category;
  Tier tier = Tier::fail;
  CandidateResult::Status status = CandidateResult::Status::missing;
  std::array<double, 3> error{};      // normwise, units of 2^-53 (infinite when missing or non-finite)
  std::array<double, 3> tolerance{};  // base + c kappa_f
  std::array<double, 3> kappa{};
  bool pass = false;
  double ratio = 0;                   // max over groups of error / tolerance
  int group = 0;                      // the group with that ratio
  int entry = 0;                      // its entry with the largest absolute difference
  double expected_value = 0, candidate_value = 0;
};

CaseOutcome compare(const Expected& e, const CandidateResult& r, const Policy& policy);

// The normwise error of one output group (n <= 144 values), ||candidate - certified||_2 / ||certified||_2
// in units of 2^-53, relative to `scale_if_zero` where the certified group is exactly zero (conformance
// uses scale_f); 0 when the two are equal, infinity when the difference is not finite.
double normwise_error(const double* candidate, const double* certified, std::size_t n, double scale_if_zero);

struct CategorySummary {
  std::string category;
  int cases = 0, missing = 0, nonfinite = 0, failed = 0;
  std::array<double, 3> median{}, worst{};  // per group, units of 2^-53
  std::string worst_id;                     // the case with the largest error / tolerance
  double worst_ratio = 0;
  bool pass = true;
  Tier tier = Tier::correctly_rounded;      // the tier every case of the category reaches
};

std::vector<CategorySummary> summarize(const std::vector<CaseOutcome>& outcomes);

// The report of hinge conform; returns whether everything passed.
bool print_report(std::ostream& out, const std::vector<CaseOutcome>& outcomes, const Policy& policy,
                  const std::string& candidate);
// The same report as JSON (hinge conform --json; docs/conformance.md, "The JSON report"), every case included.
void write_json_report(std::ostream& out, const std::vector<CaseOutcome>& outcomes, const Policy& policy,
                       const std::string& candidate);

// Mesh Hessians: normwise error of a candidate's energy Hessian (and gradient) against the certified
// ones, in units of 2^-53, and the summation condition number kappa_sum = sum_h ||H_h||_F / ||H||_F
// (H_h: hinge h's contribution; likewise for the gradient). Passes when error <= mesh_base * kappa_sum.
inline constexpr double mesh_base = 16;

// ||H||_F of a symmetric matrix stored as its upper triangle (off-diagonal entries count twice); NaN
// when an entry is.
double symmetric_frobenius(const Eigen::SparseMatrix<double>& upper);
// kappa_sum of the certified mesh's Hessian and gradient (1 where they are zero).
double hessian_kappa_sum(const CertifiedMesh& m);
double gradient_kappa_sum(const CertifiedMesh& m);

// A candidate's mesh Hessian (upper triangle, any pattern: an entry left out is a zero) or gradient
// against the certified one: error ||candidate - certified|| / ||certified|| in units of 2^-53 (relative to
// 1 where the certified output is zero), tolerance mesh_base * kappa_sum, pass when the error is finite
// and within it.
struct MeshComparison {
  double error = 0, kappa_sum = 1, tolerance = 0;
  bool pass = false;
};
MeshComparison compare_mesh_hessian(const CertifiedMesh& m, const Eigen::SparseMatrix<double>& candidate_upper);
MeshComparison compare_mesh_gradient(const CertifiedMesh& m, const std::vector<double>& candidate);

// Regenerates the committed vectors (conformance/: docs/conformance-format.md) under `dir`, bit for bit:
// hinges/<category>.jsonl, meshes/*.obj, *.mtx, *.gradient.txt and meshes/meshes.jsonl. `progress(done,
// total)` is called after each hinge case. Throws std::logic_error if a vector cannot be certified.
void write_vectors(const std::filesystem::path& dir, const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace hinge::oracle::conformance
