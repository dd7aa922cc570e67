// hinge/io/jsonl.hpp: the JSON Lines format of `hinge eval` and `hinge oracle` (docs/contract.md).
// Input: {"id": "any string", "x": [12 numbers]} per line; other fields ignored; blank lines skipped.
// Output: {"id", "theta", "grad", "hess"}, or {"id", "error"} for a hinge that cannot be evaluated, or
// {"id": null-or-id, "line": N, "error"} for a line that is not valid input.
#pragma once

#include <array>
#include <iosfwd>
#include <optional>
#include <string>

#include "hinge/core/results.hpp"

namespace hinge::io {

struct HingeLine {
  long line = 0;                            // 1-based line number in the input
  std::string id_json;                      // the id as JSON text ("null" if it could not be read)
  std::optional<std::array<double, 12>> x;  // absent when the line is not valid input
  std::string error;                        // why the line is not valid input
  std::string category;                     // the line's "category" string, if it has one (hinge study groups by it)
};

// Parses one non-blank input line. Numbers are read correctly rounded (nlohmann::json uses strtod).
HingeLine parse_hinge_line(const std::string& text, long line_number);

// One output line (without the newline).
std::string result_line(const std::string& id_json, const RoundedTheta& r);
std::string error_line(const std::string& id_json, const std::string& error);
std::string invalid_line(const HingeLine& line);
// A result line with the condition numbers of `hinge eval --cond` added: ..., "kappa": {"theta", "grad",
// "hess"}}.
std::string result_line(const std::string& id_json, const RoundedTheta& r, const std::array<double, 3>& kappa);
// An input line with its category, as `hinge conform --inputs` writes them: {"id", "category", "x"}.
std::string input_line(const std::string& id, const std::string& category, const std::array<double, 12>& x);

// Calls f(HingeLine) for every non-blank line of `in`, whose first line is numbered `first_line` (a shard
// of a larger file starts at its own line number).
template <class F>
void for_each_hinge_line(std::istream& in, F&& f, long first_line = 1);

// The loop of `hinge eval` and `hinge oracle` (and of their shards on a cluster): one output line per
// non-blank input line of `in`, in order, to `out`: write(id_json, x) for a valid line (an InputError or
// DomainError it throws becomes that hinge's error line), the invalid-line object for any other;
// after_line() after each. Lines are numbered from `first_line`.
template <class Write, class AfterLine>
void transform_hinge_lines(std::istream& in, std::ostream& out, long first_line, Write&& write, AfterLine&& after_line);

// `s` as a JSON string, quotes and escapes included (invalid UTF-8 replaced).
std::string json_string(const std::string& s);

// Whether a line holds only whitespace.
bool blank(const std::string& text);

}  // namespace hinge::io

#include <istream>
#include <ostream>

#include "hinge/core/errors.hpp"

template <class F>
void hinge::io::for_each_hinge_line(std::istream& in, F&& f, long first_line) {
  std::string text;
  long number = first_line - 1;
  while (std::getline(in, text)) {
    ++number;
    if (!blank(text)) f(parse_hinge_line(text, number));
  }
}

template <class Write, class AfterLine>
void hinge::io::transform_hinge_lines(std::istream& in, std::ostream& out, long first_line, Write&& write,
                                      AfterLine&& after_line) {
  for_each_hinge_line(
      in,
      [&](const HingeLine& line) {
        std::string text;
        if (!line.x) {
          text = invalid_line(line);
        } else {
          try {
            text = write(line.id_json, *line.x);
          } catch (const InputError& e) {
            text = error_line(line.id_json, e.what());
          } catch (const DomainError& e) {
            text = error_line(line.id_json, e.what());
          }
        }
        text += '\n';
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        after_line();
      },
      first_line);
}
