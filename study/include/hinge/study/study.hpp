// hinge/study/study.hpp: what accuracy costs in time (docs/contract.md, `hinge study`; docs/study.md).
// Every method (hinge::methods: reference, fast, autodiff, symbolic) in every scalar type, the faithful mode
// and the certified oracle (double), and implementations from outside (a plugin through hinge/candidate.h,
// a Python callable) are timed and their errors measured against the certified oracle, per category of
// hinges; the mesh level times whole evaluations per interior edge on the paper's cloth sizes and fits
// t = a n^k (the paper's Table 2 and Fig. 7).
//
// Error measures (FPBench's vocabulary): forward errors, normwise per output group, sound (against
// certified values): ||f - f*||_2 / ||f*||_2 in units of 2^-53, f* the certified outputs (each the double
// nearest the exact value, certified by the oracle with its fast path switched off, so that the oracle's
// own row, fast path on, can fail), f the row's outputs rounded to double; median and maximum over a
// category, also as bits, log2(1 + max). Where f* is exactly zero (theta on a flat hinge) the error is
// relative to the output's scale L ||J_f||_F instead (the conformance policy's scale: L the longest edge,
// J_f the output's Jacobian, from the certified derivatives). Types wider than double also get error_own:
// the same normwise error of the unrounded outputs against the reference evaluated in MPFR at
// max(2p + 32, p + 100) bits (p the type's precision), in units of the type's own unit roundoff 2^-p.
//
// Times: one method for every row (src/timing.hpp; study.json's "timing"): per hinge one call of the row's
// per-hinge function writing into the caller's arrays, over the same hinges, in rounds that run the row
// and fast in double back to back; ns per hinge the median of the row's passes, the ratio to fast the
// median of the per-round ratios.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hinge/core/scalar.hpp"
#include "hinge/io/study_json.hpp"
#include "hinge/methods/methods.hpp"
#include "hinge/study/outside.hpp"

namespace hinge::study {

// One hinge of the study: its id and category (built-in: the conformance categories; --input: the line's
// "category", default "input").
struct StudyHinge {
  std::string id, category;
  std::array<double, 12> x{};
};

// Progress: the stage ("certifying", "rows", "mesh"), and how far it has come.
using ProgressFn = std::function<void(const std::string& stage, std::size_t done, std::size_t total)>;

struct Options {
  bool quick = false;                // the quick study (docs/study.md says what it holds)
  std::vector<StudyHinge> hinges;    // empty: the built-in hinges
  std::string source = "built-in";   // the input file's name, for study.json
  std::vector<std::string> methods;  // empty: all of method_names() (parse with check_method)
  std::vector<Outside> outside;      // implementations from outside, a row each (double)
  std::vector<ScalarType> scalars;   // empty: default_scalars(quick)
  bool mesh = true;                  // the mesh level
  double budget_seconds = 0;         // per row and per mesh row; 0: the default (quick 1.5 s, full 20 s)
  ProgressFn progress;
};

// The rows' methods: reference, fast, autodiff, symbolic (hinge::methods, in every scalar type), faithful
// (fast's faithful mode) and oracle (certified; both double only).
std::vector<std::string> method_names();
// `name` if it is one of method_names(); throws std::invalid_argument naming it otherwise.
std::string check_method(const std::string& name);

// The scalar types studied by default: float, double, long-double, dd, qd, float128 (where built), bin128, mpfr:128,
// mpfr:256 (and mpfr:512 in the full study).
std::vector<ScalarType> default_scalars(bool quick);

// The built-in hinges: the conformance inputs (hinge::conformance::inputs(): well-shaped,
// rotations, scales, offsets, near-flat, near-folded, needles, short-hinge-edges, boundary-meshes), and in
// the full study 2000 more seeded well-shaped hinges (category well-shaped).
std::vector<StudyHinge> builtin_hinges(bool quick);

// The hinges of a file in the `hinge eval` input format, each line's "category" string grouping it
// (default "input"). Throws hinge::InputError naming the file and line for an unreadable file or a line
// that is not valid input, and for a file with no hinge at all.
std::vector<StudyHinge> read_hinges(const std::string& path);

// `count` of `hinges` drawn reproducibly (a fixed seed), in their original order (all of them when count
// is 0 or at least their number).
std::vector<StudyHinge> sample(const std::vector<StudyHinge>& hinges, std::size_t count);

// What a study measured: the types of study.json (hinge/io/study_json.hpp), by the study's names.
using io::ErrorStats;
using io::GroupErrors;
using io::SharedFit;
using io::Study;
using Row = io::StudyRow;
using MeshRow = io::StudyMeshRow;

// Runs the study. Throws std::invalid_argument when the methods and scalar types leave nothing to study
// (or name an unknown method),
// hinge::InputError when no input hinge can be certified.
Study run(const Options& options);

// study.md (the tables of study.json, hinge::io::write_study_json, in Markdown), the summary table printed.
void write_markdown(std::ostream& out, const Study& s);
void print_summary(std::ostream& out, const Study& s);

}  // namespace hinge::study
