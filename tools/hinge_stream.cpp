// The JSON Lines loop of hinge eval / oracle (tools/hinge_stream.hpp).
#include "hinge_stream.hpp"

#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "commands.hpp"
#include "hinge/reference/errors.hpp"
#include "jsonl.hpp"
#include "output.hpp"
#include "progress.hpp"

namespace hinge::tools {

int run_hinge_stream(const std::string& input, const std::string& output, const HingeLineWriter& write,
                     const std::string& what) {
  std::ifstream file_in;
  std::istream* in = &std::cin;
  if (!input.empty() && input != "-") {
    file_in.open(input);
    if (!file_in) {
      std::cerr << "hinge " << what << ": cannot read " << input << "\n";
      return exit_invalid_input;
    }
    in = &file_in;
  }
  std::optional<AtomicFile> file_out;
  std::ostream* out = &std::cout;
  try {
    if (!output.empty() && output != "-") out = &file_out.emplace(output).stream();
  } catch (const std::exception& e) {
    std::cerr << "hinge " << what << ": " << e.what() << "\n";
    return exit_invalid_input;
  }

  Progress progress("hinge " + what + ": hinges", 0);
  std::size_t count = 0;
  for_each_hinge_line(*in, [&](const HingeLine& line) {
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
    out->write(text.data(), static_cast<std::streamsize>(text.size()));
    progress.update(++count);
  });
  if (in->bad()) {
    std::cerr << "hinge " << what << ": reading " << (input.empty() ? "standard input" : input) << " failed\n";
    return exit_invalid_input;
  }
  try {
    out->flush();
    if (!*out) throw std::runtime_error("writing the output failed");
    if (file_out) file_out->commit();
  } catch (const std::exception& e) {
    std::cerr << "hinge " << what << ": " << e.what() << "\n";
    return exit_invalid_input;
  }
  return exit_done;
}

}  // namespace hinge::tools
