// hinge simulate SCENE.json --out DIR [--threads N] [--quiet] [--overwrite] [--dump-system STEP:ITER,...]:
// runs a scene (hinge::sim) and writes DIR/scene.json (the scene as resolved), DIR/rest.obj, DIR/final.obj,
// DIR/frames/NNNNN.obj (dynamic), DIR/summary.json and DIR/system/STEP-ITER.* (--dump-system), each
// atomically.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "commands.hpp"
#include "hinge/core/build_info.hpp"
#include "hinge/io/atomic_file.hpp"
#include "hinge/io/matrix_market.hpp"
#include "hinge/io/number.hpp"
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

// "STEP:ITER[,STEP:ITER...]" (STEP >= 0, ITER >= 1); false if malformed.
bool parse_dump_list(const std::string& text, std::vector<std::pair<int, int>>& pairs) {
  if (text.empty() || text.back() == ',') return false;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    int step = -1, iteration = -1;
    char colon = 0;
    std::istringstream one(item);
    if (!(one >> step >> colon >> iteration) || colon != ':' || step < 0 || iteration < 1 || !one.eof()) return false;
    pairs.emplace_back(step, iteration);
  }
  return !pairs.empty();
}

// DIR/system/STEP-ITER.{mtx,solved.mtx,g,obj} (the contract's --dump-system).
void write_system(const fs::path& folder, const sim::SystemDump& d, const std::string& scene) {
  fs::create_directories(folder);
  std::string stem = std::to_string(d.step);
  stem += '-';
  stem += std::to_string(d.iteration);
  const std::string where =
      scene + ", step " + std::to_string(d.step) + ", Newton iteration " + std::to_string(d.iteration);
  {
    io::AtomicFile f((folder / (stem + ".mtx")).string());
    io::write_matrix_market(f.stream(), d.hessian,
                            "hinge simulate: the true Hessian on the free coordinates, " + where);
    f.commit();
  }
  {
    io::AtomicFile f((folder / (stem + ".solved.mtx")).string());
    io::write_matrix_market(f.stream(), d.factored, "hinge simulate: the matrix factored, " + where);
    f.commit();
  }
  {
    io::AtomicFile f((folder / (stem + ".g")).string());
    for (Eigen::Index i = 0; i < d.gradient.size(); ++i) f.stream() << io::format_double(d.gradient[i]) << "\n";
    f.commit();
  }
  write_mesh(folder / (stem + ".obj"), *d.state, "hinge simulate: the state of " + where);
}

}  // namespace

Action add_simulate(CLI::App& app) {
  auto* cmd = app.add_subcommand("simulate", "Run a scene: static equilibrium or backward Euler (docs/simulator.md)");
  struct Options {
    std::string scene, out, dump, newton_log;
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
  cmd->add_option("--newton-log", o->newton_log,
                  "Write FILE: one JSON line per Newton iteration (step, iteration, rung, residual / F, energy, "
                  "step / L, alpha, boundary): where a run's iterations go");
  cmd->add_option("--dump-system", o->dump,
                  "STEP:ITER[,STEP:ITER...]: write DIR/system/STEP-ITER.mtx (the true Hessian), .solved.mtx (the "
                  "matrix factored), .g (the gradient) and .obj (the state) of those Newton iterations (steps from "
                  "1, a static solve's 0; iterations from 1)");
  cmd->footer(
      "Exit: 0 done; 1 invalid scene (the message names the file and the key) or a run that could not go\n"
      "on (summary.json says why; the frames so far stay); 2 usage error (also: --out holds earlier\n"
      "outputs and --overwrite is not given; --dump-system named an iteration that never occurred: the\n"
      "outputs stay, the missing ones are listed).");
  return [o]() {
    const fs::path out(o->out);
    const fs::path final_obj = out / "final.obj", summary_file = out / "summary.json", frames = out / "frames",
                   scene_file = out / "scene.json", rest_obj = out / "rest.obj", system = out / "system";
    const bool earlier = fs::exists(final_obj) || fs::exists(summary_file) || fs::exists(frames) ||
                         fs::exists(scene_file) || fs::exists(rest_obj) || fs::exists(system);
    if (earlier && !o->overwrite) {
      std::cerr << "hinge simulate: " << o->out
                << " holds the outputs of an earlier run (give --overwrite to replace them)\n";
      return exit_usage;
    }
    std::vector<std::pair<int, int>> dumps;
    if (!o->dump.empty() && !parse_dump_list(o->dump, dumps)) {
      std::cerr << "hinge simulate: --dump-system: expected STEP:ITER[,STEP:ITER...] (STEP >= 0, ITER >= 1), got '"
                << o->dump << "'\n";
      return exit_usage;
    }
    return run_mesh_command("simulate", [&] {
      const sim::Scene scene = sim::read_scene(o->scene);
      fs::create_directories(out);
      if (o->overwrite) {
        fs::remove(final_obj), fs::remove(summary_file), fs::remove(scene_file), fs::remove(rest_obj);
        fs::remove_all(frames), fs::remove_all(system);
      }
      write_atomically(scene_file, io::resolved_scene_json(scene, out.string()));
      write_mesh(rest_obj, scene.rest, "hinge simulate: " + scene.name + ", the rest shape");
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
      std::set<std::pair<int, int>> dumped;
      run.dump = dumps;
      run.on_dump = [&](const sim::SystemDump& d) {
        write_system(system, d, scene.name);
        dumped.emplace(d.step, d.iteration);
      };
      std::unique_ptr<io::AtomicFile> log;
      if (!o->newton_log.empty()) {
        log = std::make_unique<io::AtomicFile>(o->newton_log);
        run.on_iteration = [&](const sim::IterationReport& r) {
          log->stream() << "{\"step\": " << r.step << ", \"iteration\": " << r.iteration << ", \"rung\": \"" << r.rung
                        << "\", \"residual\": " << io::format_double(r.residual)
                        << ", \"energy\": " << io::format_double(r.energy)
                        << ", \"step_length\": " << io::format_double(r.step_length)
                        << ", \"alpha\": " << io::format_double(r.alpha)
                        << ", \"boundary\": " << (r.boundary ? "true" : "false") << "}\n";
        };
      }
      Mesh last;
      const sim::Summary summary = sim::simulate(scene, run, last);
      if (log) log->commit();
      if (summary.ok) write_mesh(final_obj, last, "hinge simulate: " + scene.name + ", final state");
      write_atomically(summary_file, io::summary_json(summary, build_description()));
      std::string missing;
      for (const auto& [step, iteration] : dumps)
        if (!dumped.count({step, iteration})) {
          missing += missing.empty() ? " " : ", ";
          missing += std::to_string(step);
          missing += ':';
          missing += std::to_string(iteration);
        }
      if (!missing.empty())
        std::cerr << "hinge simulate: --dump-system: these Newton iterations never occurred:" << missing << "\n";
      if (!summary.ok) {
        std::cerr << "hinge simulate: " << scene.name << ": failed: " << summary.reason << "\n";
        return exit_invalid_input;
      }
      std::printf("%s: ok, %d steps, %lld Newton iterations, %.3g s (linear solve %.1f%%, bending %.1f%%)\n",
                  scene.name.c_str(), summary.steps, summary.newton_iterations, summary.time_total,
                  summary.time_total > 0 ? 100 * summary.time_linear_solve / summary.time_total : 0.0,
                  100 * summary.bending_share);
      return missing.empty() ? exit_done : exit_usage;
    });
  };
}

}  // namespace hinge::tools
