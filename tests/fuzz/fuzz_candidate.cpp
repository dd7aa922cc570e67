// Fuzz target: the reader of a candidate's results (`hinge conform --candidate`, hinge/io/eval_output.hpp).
// Every result read is missing, an error, non-finite, or finite throughout (check_finite's promise), and
// writes back as one line of valid JSON.
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fuzz_target.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/eval_output.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using hinge::fuzz::require;
  using Status = hinge::io::EvalOutput::Status;
  std::istringstream in(hinge::fuzz::as_string(data, size));
  try {
    const auto results = hinge::io::read_eval_outputs(in, "fuzz.jsonl");
    for (const auto& [id, r] : results) {
      if (r.status == Status::ok) {
        bool finite = std::isfinite(r.theta);
        for (double g : r.grad) finite = finite && std::isfinite(g);
        for (double h : r.hess) finite = finite && std::isfinite(h);
        require(finite, "a result with a NaN or an infinity is ok");
      }
      const std::string line = hinge::io::eval_output_line(id, r);
      require(line.find('\n') == std::string::npos, "an output line holds a newline");
      require(nlohmann::json::accept(line), "an output line is not valid JSON");
    }
  } catch (const hinge::InputError&) {
  }
  return 0;
}
