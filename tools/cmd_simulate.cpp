// hinge simulate SCENE.json --out DIR [--threads N] [--quiet] [--overwrite]: runs a scene (hinge::sim) and
// writes DIR/final.obj, DIR/frames/NNNNN.obj (dynamic) and DIR/summary.json, each atomically.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "commands.hpp"
#include "hinge/core/build_info.hpp"
#include "hinge/io/atomic_file.hpp"
#include "hinge/io/obj.hpp"
#include "hinge/io/summary.hpp"
#include "hinge/sim/scene.hpp"
#include "hinge/sim/simulation.hpp"
#include "mesh_job.hpp"
#include "progress.hpp"

namespace hinge::tools {
namespace {

namespace fs = std::filesystem;

void write_atomically(const fs::path& path, const std::string& text) {
  io::AtomicFile file(path.string());
  file.stream() << text;
  file.commit();
}

void write_mesh(const fs::path& path, const Mesh& mesh, const std::string& comment) {
  io::AtomicFile file(path.string());
  io::write_obj(file.stream(), mesh, comment);
  file.commit();
}

}  // namespace

Action add_simulate(CLI::App& app) {
  auto* cmd = app.add_subcommand("simulate", "Run a scene: static equilibrium or backward Euler (docs/simulator.md)");
  struct Options {
    std::string scene, out;
    int threads = 1;
    bool quiet = false, overwrite = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("scene", o->scene, "The scene file (JSON)")->required();
  cmd->add_option("--out", o->out, "Output folder: final.obj, frames/, summary.json")->required();
  cmd->add_option("--threads", o->threads, "Threads for the bending assembly (no output bit depends on it)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  cmd->add_flag("--quiet", o->quiet, "No progress on standard error");
  cmd->add_flag("--overwrite", o->overwrite, "Replace the outputs of an earlier run in --out");
  cmd->footer(
      "Exit: 0 done; 1 invalid scene (the message names the file and the key) or a run that could not go\n"
      "on (summary.json says why; the frames so far stay); 2 usage error (also: --out holds earlier\n"
      "outputs and --overwrite is not given).");
  return [o]() {
    const fs::path out(o->out);
    const fs::path final_obj = out / "final.obj", summary_file = out / "summary.json", frames = out / "frames";
    const bool earlier = fs::exists(final_obj) || fs::exists(summary_file) || fs::exists(frames);
    if (earlier && !o->overwrite) {
      std::cerr << "hinge simulate: " << o->out
                << " holds the outputs of an earlier run (give --overwrite to replace them)\n";
      return exit_usage;
    }
    return run_mesh_command("simulate", [&] {
      const sim::Scene scene = sim::read_scene(o->scene);
      fs::create_directories(out);
      if (o->overwrite) {
        fs::remove(final_obj), fs::remove(summary_file);
        fs::remove_all(frames);
      }
      const bool dynamic = scene.solve.mode == sim::Mode::dynamic;
      Progress progress(dynamic ? "hinge simulate: steps" : "hinge simulate: Newton iterations",
                        static_cast<std::size_t>(dynamic ? scene.solve.steps : scene.solve.max_newton));
      sim::RunOptions run;
      run.threads = o->threads;
      if (!o->quiet)
        run.on_progress = [&](long long done, long long) { progress.update(static_cast<std::size_t>(done)); };
      run.on_frame = [&](int index, const Mesh& state) {
        if (index == 0) fs::create_directories(frames);
        char name[32];
        std::snprintf(name, sizeof name, "%05d.obj", index);
        write_mesh(frames / name, state, "hinge simulate: " + scene.name + ", frame " + std::to_string(index));
      };
      Mesh last;
      const sim::Summary summary = sim::simulate(scene, run, last);
      if (summary.ok) write_mesh(final_obj, last, "hinge simulate: " + scene.name + ", final state");
      write_atomically(summary_file, io::summary_json(summary, build_description()));
      if (!summary.ok) {
        std::cerr << "hinge simulate: " << scene.name << ": failed: " << summary.reason << "\n";
        return exit_invalid_input;
      }
      std::printf("%s: ok, %d steps, %lld Newton iterations, %.3g s (linear solve %.1f%%, bending %.1f%%)\n",
                  scene.name.c_str(), summary.steps, summary.newton_iterations, summary.time_total,
                  summary.time_total > 0 ? 100 * summary.time_linear_solve / summary.time_total : 0.0,
                  100 * summary.bending_share);
      return exit_done;
    });
  };
}

}  // namespace hinge::tools
