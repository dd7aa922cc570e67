// tools/hinge_stream.hpp: the JSON Lines loop shared by `hinge eval` and `hinge oracle`.
#pragma once

#include <functional>
#include <array>
#include <string>

namespace hinge::tools {

// The output line (without its newline) for the hinge `x` whose id is `id_json` (the id as JSON text);
// may throw InputError or DomainError, which become error lines.
using HingeLineWriter = std::function<std::string(const std::string& id_json, const std::array<double, 12>& x)>;

// Reads hinges from `input` ("-" or empty: standard input), writes one result line per hinge to `output`
// ("-" or empty: standard output; a file appears only when complete). Per-hinge errors become error
// lines. Returns the exit status: 0 when every line was read, 1 on an I/O failure.
int run_hinge_stream(const std::string& input, const std::string& output, const HingeLineWriter& write,
                     const std::string& what);

}  // namespace hinge::tools
