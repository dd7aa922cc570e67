// hinge/io/eval_output.hpp: reading the output format of `hinge eval` back (docs/contract.md: one object per
// line, {"id", "theta", "grad": [12], "hess": [144]} or {"id", "error"}), as `hinge conform --candidate`
// reads a candidate implementation's results. Lenient where a candidate's numbers are bad (a NaN, null,
// a missing array: that case is non-finite or missing, the others still count), strict where the file
// itself is unusable (no readable id on a line).
#pragma once

#include <array>
#include <iosfwd>
#include <map>
#include <string>

namespace hinge::io {

// One result line.
struct EvalOutput {
  enum class Status { missing, error, nonfinite, ok };
  Status status = Status::missing;
  std::string error;  // the line's "error", or why it is missing
  double theta = 0;
  std::array<double, 12> grad{};
  std::array<double, 144> hess{};  // row-major
};

// When r is ok: missing ("a NaN in the outputs": not evaluated) when it holds a NaN, else nonfinite when it
// holds an infinity (docs/contract.md, "Conformance from Python": the same rule on every route).
void check_finite(EvalOutput& r);

// The results of a file by id (the first line of an id counts); a line that is not JSON but whose "id" can
// be found counts as missing if it has a NaN token in it, else as non-finite (an "Infinity" token); null
// and "NaN" for a number are NaN, "Infinity" an infinity. Throws hinge::InputError "FILE:LINE: why" when a
// line has no readable id, or the file cannot be read.
std::map<std::string, EvalOutput> read_eval_outputs(const std::string& path);
std::map<std::string, EvalOutput> read_eval_outputs(std::istream& in, const std::string& name_for_errors);

// `r` as a line of `hinge eval` output (without the newline): an error line for anything not ok.
std::string eval_output_line(const std::string& id, const EvalOutput& r);

}  // namespace hinge::io
