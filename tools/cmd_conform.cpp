// hinge conform --inputs | --candidate FILE | --plugin LIB.so [--symbol NAME] (CONVENTIONS.md).
// Not implemented yet (issue 6): the command exists so that its options are reserved; it exits with 2.
#include <iostream>

#include "commands.hpp"

namespace hinge::tools {

Action add_conform(CLI::App& app) {
  auto* cmd = app.add_subcommand("conform", "Check another implementation against certified values (issue 6)");
  cmd->allow_extras();
  return []() -> int {
    std::cerr << "hinge conform: not implemented yet\n";
    return exit_usage;
  };
}

}  // namespace hinge::tools
