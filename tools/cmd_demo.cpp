// hinge demo: the main job on built-in defaults (the README's first command): the quick study (what
// accuracy costs in time: every method in every scalar type against the certified oracle, written to
// --out with its plots) and the conformance verdict of the fast kernel in double (hinge conform --method
// fast).
#include <iostream>

#include "commands.hpp"
#include "hinge/study/study.hpp"

namespace hinge::tools {

Action add_demo(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "demo", "The main job on built-in defaults: the quick study and the fast kernel's conformance");
  auto out = std::make_shared<std::string>("study");
  cmd->add_option("--out", *out, "Where the quick study writes study.json, study.md and its plots")
      ->capture_default_str();
  cmd->footer(
      "Runs `hinge study --quick --out DIR`, then `hinge conform --method fast`. Exit: 0 when both succeed\n"
      "(the fast kernel within the conformance policy), 1 otherwise.");
  return [out]() -> int {
    study::Options options;
    options.quick = true;
    std::cout << "== hinge study --quick: what accuracy costs in time (docs/study.md)\n" << std::flush;
    const int studied = run_study(options, *out, true);
    std::cout << "\n== hinge conform --method fast: the fast kernel in double against the certified oracle "
                 "(docs/conformance.md)\n"
              << std::flush;
    const int conformed = conform_method("fast", "double");
    return studied == exit_done && conformed == exit_done ? exit_done : exit_invalid_input;
  };
}

}  // namespace hinge::tools
