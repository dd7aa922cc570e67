// Fuzz target: the JSON Lines hinge reader of `hinge eval` and `hinge oracle` (hinge/io/jsonl.hpp). Every
// line is either a hinge (12 coordinates, none NaN: JSON has none; a number beyond double's range reads as
// an infinity, which the evaluation reports as "not finite") or an invalid line with a reason; the line
// numbers count up; the invalid line it would print is one line of valid JSON.
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fuzz_target.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/jsonl.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using hinge::fuzz::require;
  std::istringstream in(hinge::fuzz::as_string(data, size));
  long last = 0;
  try {
    hinge::io::for_each_hinge_line(in, [&](const hinge::io::HingeLine& h) {
      require(h.line > last, "line numbers do not count up");
      last = h.line;
      if (h.x) {
        for (double c : *h.x) require(!std::isnan(c), "a NaN coordinate was accepted");
      } else {
        require(!h.error.empty(), "an invalid line without a reason");
        const std::string out = hinge::io::invalid_line(h);
        require(out.find('\n') == std::string::npos, "an output line holds a newline");
        require(nlohmann::json::accept(out), "an output line is not valid JSON");
      }
      require(nlohmann::json::accept(h.id_json), "the id is not valid JSON");
    });
  } catch (const hinge::InputError&) {
  }
  return 0;
}
