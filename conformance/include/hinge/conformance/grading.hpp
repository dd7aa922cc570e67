// hinge/conformance/grading.hpp: a candidate's outputs against the certified ones (docs/conformance.md):
// the certified expectations with their condition numbers, the tolerance policy and its tiers, the
// normwise comparison of a hinge's output groups, and of a mesh's Hessian and gradient.
#pragma once

#include <Eigen/SparseCore>
#include <array>
#include <string>
#include <vector>

#include "hinge/conformance/inputs.hpp"
#include "hinge/io/eval_output.hpp"
#include "hinge/oracle/conditioning.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {

using oracle::CertifiedMesh;
using oracle::CertifiedTheta;
using oracle::Conditioning;

// The groups of outputs compared separately: theta, grad (12), hess (144); for a bending energy psi (named
// "energy"), its gradient and Hessian.
inline constexpr std::array<const char*, 3> group_names{"theta", "grad", "hess"};
inline constexpr std::array<const char*, 3> energy_group_names{"energy", "grad", "hess"};

struct Expected {
  Case input;
  CertifiedTheta values;
  Conditioning conditioning;
};

// Certified outputs (stages 1 and 2 of the oracle: the same doubles as its fast path) and conditioning
// of `c` (hinge/oracle/conditioning.hpp). Throws as certified_theta_derivatives does.
Expected expected(const Case& c);

// The floating-point format a candidate is graded in: its unit roundoff u is the unit of every error
// (2^-53 for float64, 2^-24 for float32), and with float32 the candidate's outputs are rounded to float
// before grading, against the exact values correctly rounded to float (docs/conformance.md, "float32").
enum class Dtype { float64, float32 };
double unit_roundoff(Dtype d);          // 2^-53, 2^-24
const char* dtype_name(Dtype d);        // "float64", "float32"
Dtype parse_dtype(const std::string&);  // std::invalid_argument naming the choices

// The tolerance policy: output group f of a case passes when its normwise error, in units of
// u (2^-53 in float64) relative to ||f||_2 (to scale_f where f is exactly zero), is at most  base + c * kappa_f.
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
// the certified one; every output group within 1 unit of u (normwise, as the errors are measured);
// within 4 units; within the tolerance policy; outside it but within `approximate_bound` (the formula
// looks right and is not accurate); outside that. `approximate` and `fail` are not passed.
enum class Tier { correctly_rounded, faithful, four_units, policy, approximate, fail };
// "correctly-rounded", "faithful", "4u", "policy", "approximate", "fail" (docs/contract.md).
const char* tier_name(Tier t);
Tier parse_tier(const std::string& name);  // std::invalid_argument naming the choices

// The bound of the tier `approximate`, in units of u, per unit of (1 + kappa_f): a relative error of
// 2^-20 in float64, 2^-8 in float32 (docs/conformance.md).
double approximate_bound(Dtype d);

// How a candidate is graded: the policy, the format, and which output groups it gave (theta, grad,
// hess: a group not given is not graded, and its errors are NaN).
struct Grading {
  Policy policy;
  Dtype dtype = Dtype::float64;
  std::array<bool, 3> given{true, true, true};
  bool energy = false;  // the outputs are a bending term's psi, gradient and Hessian (energy_report.hpp)
  // The best tier a passing case is given: Tier::policy where a reference is not certified (the projected
  // Hessian's 256-bit evaluation), so that no tier claims more than the reference can.
  Tier best = Tier::correctly_rounded;
};
// The name of output group g as `grading` grades it ("theta" or "energy", "grad", "hess").
const char* group_name(const Grading& grading, int g);

struct CaseOutcome {
  std::string id, category;
  Tier tier = Tier::fail;
  CandidateResult::Status status = CandidateResult::Status::missing;
  std::array<double, 3> error{};      // normwise, units of u (infinite when missing or non-finite, NaN when
                                      // the group was not given)
  std::array<double, 3> tolerance{};  // base + c kappa_f
  std::array<double, 3> kappa{};
  bool pass = false;
  double ratio = 0;  // max over groups of error / tolerance
  int group = 0;     // the group with that ratio
  int entry = 0;     // its entry with the largest absolute difference
  double expected_value = 0, candidate_value = 0;
};

// `r` graded against `e`. With Dtype::float32, `r`'s values are first rounded to float (an infinity when
// they overflow it); `e` holds the expected values of that format.
CaseOutcome compare(const Expected& e, const CandidateResult& r, const Grading& grading);

// `r` rounded to the format (float32: each value to the nearest float, kept as a double; float64: as is).
CandidateResult rounded_to(Dtype d, CandidateResult r);

// The normwise error of one output group (n <= 144 values), ||candidate - certified||_2 / ||certified||_2
// in units of u (default 2^-53), relative to `scale_if_zero` where the certified group is exactly zero (conformance
// uses scale_f); 0 when the two are equal, infinity when the difference is not finite.
double normwise_error(const double* candidate, const double* certified, std::size_t n, double scale_if_zero,
                      double u = 0x1p-53);

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

}  // namespace hinge::conformance
