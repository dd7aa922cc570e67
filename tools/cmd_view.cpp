// hinge view DIR [--out FILE.html]: one self-contained page that plays a simulation's frames, each hinge
// coloured by |theta - theta_bar| (hinge::view; docs/view.md), written atomically.
#include <cstdio>
#include <filesystem>

#include "commands.hpp"
#include "hinge/io/atomic_file.hpp"
#include "hinge/view/page.hpp"
#include "hinge/view/run.hpp"
#include "mesh_job.hpp"

namespace hinge::tools {

Action add_view(CLI::App& app) {
  auto* cmd = app.add_subcommand("view", "Watch a simulation in a web browser, coloured by its bending (docs/view.md)");
  struct Options {
    std::string folder, out;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("folder", o->folder, "The output folder of hinge simulate")->required();
  cmd->add_option("--out", o->out, "The page to write (default: FOLDER/view.html)");
  cmd->footer(
      "Exit: 0 done; 1 not a simulation's output folder, nothing to show (a static run that failed), or frames\n"
      "that do not fit together (the message names the folder or the frame; no page is left behind); 2 usage\n"
      "error.");
  return [o]() {
    return run_mesh_command("view", [&] {
      const view::Run run = view::read_run(o->folder);
      const std::string out = o->out.empty() ? (std::filesystem::path(o->folder) / "view.html").string() : o->out;
      io::AtomicFile file(out);
      const view::PageStats stats = view::write_page(file.stream(), run);
      file.commit();
      std::printf("%s: %zu frames, %zu hinges, |theta - theta_bar| up to %.3g rad (%s)\n", out.c_str(), stats.frames,
                  stats.hinges, stats.scale, run.status.c_str());
      return exit_done;
    });
  };
}

}  // namespace hinge::tools
