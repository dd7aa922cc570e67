// hinge/io/study_json.hpp: study.json (docs/contract.md, `hinge study`): what a study measured, and its
// writer. hinge::study fills these; every number is written so that it reads back exactly.
#pragma once

#include <array>
#include <cstddef>
#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hinge/core/method.hpp"
#include "hinge/core/scalar.hpp"

namespace hinge::io {

struct ErrorStats {
  double median = 0, max = 0;  // units of 2^-53 (error_u) or of the type's own u (error_own)
};
using GroupErrors = std::array<ErrorStats, 3>;  // theta, grad, hess

struct StudyRow {
  std::string method = "fast";  // a method of hinge::methods, "faithful", "oracle", or an outside row's label
  ScalarType scalar;
  bool outside = false;                          // an implementation from outside (a plugin, a Python callable)
  std::array<double, 3> ns_per_hinge{};          // theta; theta and gradient; all three (0: not timed)
  std::array<double, 3> x_fast{};                // the median of the per-round ratios to fast in double, per group
  std::size_t rounds = 0;                        // timing rounds (study.json's "timing")
  std::map<std::string, double> escalation;      // oracle: per category, the hinges its fast path left undecided
  std::string error;                             // why an outside row has no time (a crash, a time-out), or ""
  std::map<std::string, GroupErrors> error_u;    // per category, outputs rounded to double
  std::map<std::string, GroupErrors> error_own;  // per category, types wider than double
  std::vector<double> hess_errors;               // per hinge measured (units of 2^-53), for the histogram
  std::size_t hinges = 0;     // hinges whose errors were measured (fewer than all when the budget ran out)
  std::size_t failed = 0;     // reported as not evaluable (an InputError or DomainError)
  std::size_t nonfinite = 0;  // returned a NaN or an infinity, or a value outside double's range
  double seconds = 0;         // what the row took
  bool on_frontier = false;   // no other row is both faster (theta, gradient and Hessian) and more accurate
  double worst = 0;           // the largest error of any output group and category (units of 2^-53)
  double worst_hess = 0;      // the largest Hessian error of any category
};

// The row's name in tables and plots: "fast/double"; an outside row's label alone.
std::string row_label(const StudyRow& r);

struct StudyMeshRow {
  Method method = Method::fast;
  ScalarType scalar;
  std::vector<double> vertices, interior_edges, seconds;  // per size: n^2, hinges, seconds per evaluation
  std::vector<double> ns_per_edge;
  double k = 0, ln_a = 0;  // seconds per evaluation = a vertices^k, fitted in log-log (needs two sizes)
};

// The paper's Table 2 for double: k shared by the methods (the mean of their fitted k over the paper's
// sizes, 11^2 .. 81^2), each method's ln a refitted with it; fast's speedup over each is
// exp(ln a_M - ln a_fast). Empty (no ln_a) when fewer than two methods have two sizes.
struct SharedFit {
  double k = 0;
  std::vector<std::pair<std::string, double>> ln_a;  // method, ln a
  double fast_ln_a = 0;
  bool has_fast = false;
};

struct Study {
  std::string cpu;
  double clock_ghz = 0;
  std::string source;
  std::size_t hinges = 0, skipped = 0;  // skipped: input hinges the oracle rejects (degenerate, ...)
  std::vector<std::string> categories;
  std::vector<StudyRow> rows;
  std::vector<StudyMeshRow> mesh;
  SharedFit shared_fit;                                     // of the mesh rows in double
  std::vector<std::pair<std::string, std::string>> timing;  // how every row was timed (study.json's "timing")
  std::vector<std::pair<std::string, std::string>> build;   // version, commit, compiler, flags, libraries
  bool quick = false;
  double seconds = 0;
  double timing_seconds = 0;  // the timing phase (every row's rounds in turn)
};

// Bits of error: log2(1 + units), FPBench's measure (0 for an exact result, 53 for one with no correct bit).
double error_bits(double units);

// study.json, version 2 (version 1 and "timing"; rows "faithful", "oracle" and outside rows).
void write_study_json(std::ostream& out, const Study& s);

}  // namespace hinge::io
