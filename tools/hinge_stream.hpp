// tools/hinge_stream.hpp: the JSON Lines loop shared by `hinge eval` and `hinge oracle`.
#pragma once

#include <functional>
#include <string>

#include "hinge/reference/rounded.hpp"

namespace hinge::tools {

using HingeEvaluator = std::function<reference::RoundedTheta(const std::array<double, 12>&)>;

// Reads hinges from `input` ("-" or empty: standard input), writes one result line per hinge to `output`
// ("-" or empty: standard output; a file appears only when complete). Per-hinge errors become error
// lines. Returns the exit status: 0 when every line was read, 1 on an I/O failure.
int run_hinge_stream(const std::string& input, const std::string& output, const HingeEvaluator& evaluate,
                     const std::string& what);

}  // namespace hinge::tools
