// tools/commands.hpp: the subcommands of `hinge`. Each file cmd_*.cpp parses its options and calls the
// libraries; no numerics live in tools/. Exit statuses (docs/contract.md): 0 done, 1 invalid input or
// I/O failure, 2 usage error.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace hinge::study {
struct Options;  // hinge/study/study.hpp: only `hinge study` and `hinge demo` include it
}  // namespace hinge::study

namespace hinge::tools {

// A subcommand registers its options on `app` and returns the action to run after parsing.
using Action = std::function<int()>;

Action add_eval(CLI::App& app);      // hinge eval
Action add_oracle(CLI::App& app);    // hinge oracle (hinges, or --mesh)
Action add_hessian(CLI::App& app);   // hinge hessian
Action add_demo(CLI::App& app);      // hinge demo: the main job on built-in defaults
Action add_conform(CLI::App& app);   // hinge conform: check another implementation
Action add_study(CLI::App& app);     // hinge study: what accuracy costs in time
Action add_simulate(CLI::App& app);  // hinge simulate: run a scene
Action add_view(CLI::App& app);      // hinge view: a simulation's page

constexpr int exit_done = 0, exit_invalid_input = 1, exit_usage = 2;

// The work of `hinge study` after parsing (cmd_study.cpp): runs the study, writes DIR/study.json and
// DIR/study.md, renders the plots (unless `plots` is false), prints the summary. Returns the exit status.
int run_study(const study::Options& options, const std::string& out, bool plots);
// `hinge conform --method M --scalar S` (cmd_conform.cpp): prints the report, returns the exit status.
int conform_method(const std::string& method, const std::string& scalar);

}  // namespace hinge::tools
