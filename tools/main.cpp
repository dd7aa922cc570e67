// hinge: the command-line tool (docs/contract.md). `hinge --help` lists the subcommands.
#include <iostream>

#include "commands.hpp"
#include "hinge/core/errors.hpp"
#include "version.hpp"

int main(int argc, char** argv) {
  using namespace hinge::tools;
  CLI::App app{"hinge: discrete bending forces and their Jacobians (Tamstorf & Grinspun 2013)", "hinge"};
  app.set_version_flag("--version",
                       std::string("hinge ") + HINGE_VERSION + " (contract version " + HINGE_CONTRACT_VERSION + ")");
  app.require_subcommand(1);
  const std::vector<std::pair<CLI::App*, Action>> commands = [&] {
    std::vector<std::pair<CLI::App*, Action>> c;
    for (auto add : {add_eval, add_oracle, add_hessian, add_conform, add_study, add_simulate, add_view, add_demo}) {
      Action action = add(app);
      c.emplace_back(app.get_subcommands({}).back(), std::move(action));
    }
    return c;
  }();
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return exit_usage;
  }
  try {
    for (const auto& [cmd, action] : commands)
      if (cmd->parsed()) return action();
  } catch (const std::invalid_argument& e) {  // a bad option value found after parsing
    std::cerr << "hinge: " << e.what() << "\n";
    return exit_usage;
  }
  return exit_usage;
}
