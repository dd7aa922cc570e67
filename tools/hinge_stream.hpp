// tools/hinge_stream.hpp: the JSON Lines loop shared by `hinge eval` and `hinge oracle`: read hinges, write
// one result line per input line, in order (docs/contract.md).
#pragma once

#include <array>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

#include "commands.hpp"
#include "hinge/io/atomic_file.hpp"
#include "hinge/io/jsonl.hpp"
#include "progress.hpp"

namespace hinge::tools {

// The input ("-" or empty: standard input) and the output ("-" or empty: standard output; a file appears
// only when complete) of a stream.
class HingeStream {
 public:
  HingeStream(std::string input, std::string output, std::string what);
  bool open();  // false, with a message on standard error, when a file cannot be opened
  std::istream& in() { return *in_; }
  std::ostream& out() { return *out_; }
  int finish();  // the exit status: 0, or 1 (message on standard error) when reading or writing failed

 private:
  std::string input_, output_, what_;
  std::ifstream file_in_;
  std::optional<io::AtomicFile> file_out_;
  std::istream* in_ = &std::cin;
  std::ostream* out_ = &std::cout;
};

// Reads hinges from `input`, writes write(id_json, x) for each valid line to `output`
// (io::transform_hinge_lines). Returns the exit status: 0 when every line was read, 1 on an I/O failure.
template <class Write>
int run_hinge_stream(const std::string& input, const std::string& output, const std::string& what, Write&& write) {
  HingeStream stream(input, output, what);
  if (!stream.open()) return exit_invalid_input;
  Progress progress("hinge " + what + ": hinges", 0);
  std::size_t count = 0;
  io::transform_hinge_lines(stream.in(), stream.out(), 1, write, [&] { progress.update(++count); });
  return stream.finish();
}

}  // namespace hinge::tools
