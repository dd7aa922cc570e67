// tools/commands.hpp: the subcommands of `hinge`. Each file cmd_*.cpp parses its options and calls the
// libraries; no numerics live in tools/. Exit statuses (docs/contract.md): 0 done, 1 invalid input or
// I/O failure, 2 usage error.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace hinge::tools {

// A subcommand registers its options on `app` and returns the action to run after parsing.
using Action = std::function<int()>;

Action add_eval(CLI::App& app);     // hinge eval
Action add_oracle(CLI::App& app);   // hinge oracle (hinges, or --mesh)
Action add_hessian(CLI::App& app);  // hinge hessian
Action add_demo(CLI::App& app);     // hinge demo: the main job on built-in defaults
Action add_conform(CLI::App& app);  // hinge conform: check another implementation

constexpr int exit_done = 0, exit_invalid_input = 1, exit_usage = 2;

}  // namespace hinge::tools
