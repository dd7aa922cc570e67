// A simulation's output folder read for `hinge view` (hinge/view/run.hpp).
#include "hinge/view/run.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "hinge/core/errors.hpp"
#include "hinge/io/obj.hpp"

namespace hinge::view {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void not_an_output_folder(const std::string& folder, const std::string& why) {
  throw InputError(folder + ": not a simulation's output folder (" + why + ")");
}

// summary.json's "status" and "reason" (the rest of it is not shown).
void read_status(const fs::path& file, Run& run) {
  std::ifstream in(file);
  nlohmann::json summary;
  try {
    summary = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(file.string() + ": not JSON: " + e.what());
  }
  const auto status = summary.find("status");
  if (!summary.is_object() || status == summary.end() || !status->is_string())
    throw InputError(file.string() + ": status: required key missing or not a string");
  run.status = status->get<std::string>();
  const auto reason = summary.find("reason");
  if (reason != summary.end() && reason->is_string()) run.reason = reason->get<std::string>();
}

// frames/00000.obj, 00001.obj, ... in order; a gap in the sequence is an error naming the missing frame.
std::vector<fs::path> frame_files(const fs::path& frames) {
  std::vector<fs::path> files;
  if (!fs::is_directory(frames)) return files;
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(frames)) {
    const std::string name = entry.path().filename().string();
    if (name.size() == 9 && name.ends_with(".obj") && name.find_first_not_of("0123456789") == 5) ++count;
  }
  for (std::size_t i = 0; i < count; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "%05zu.obj", i);
    if (!fs::exists(frames / name))
      throw InputError((frames / name).string() + ": missing (the frames must run from 00000.obj without a gap)");
    files.push_back(frames / name);
  }
  return files;
}

// A frame read and checked against the rest shape: the same vertex count and the same faces.
Frame read_frame(const fs::path& file, double time, const Mesh& rest) {
  Mesh m = io::read_obj(file.string());
  if (m.vertices.size() != rest.vertices.size()) {
    std::string why = file.string();
    why += ": ";
    why += std::to_string(m.vertices.size());
    why += " vertices where rest.obj has ";
    why += std::to_string(rest.vertices.size());
    why += " (the frames do not fit together)";
    throw InputError(why);
  }
  if (m.faces != rest.faces)
    throw InputError(file.string() + ": its faces differ from rest.obj's (the frames do not fit together)");
  return Frame{file.string(), time, std::move(m.vertices)};
}

}  // namespace

Run read_run(const std::string& folder) {
  const fs::path dir(folder);
  if (!fs::is_directory(dir)) not_an_output_folder(folder, "not a folder");
  for (const char* name : {"summary.json", "scene.json", "rest.obj"})
    if (!fs::is_regular_file(dir / name)) not_an_output_folder(folder, std::string("no ") + name);

  Run run;
  run.folder = folder;
  const io::Scene scene = io::read_scene((dir / "scene.json").string());
  run.name = scene.name;
  run.dynamic = scene.solve.mode == io::Mode::dynamic;
  run.sphere = scene.sphere;
  if (scene.gravity) run.gravity = scene.gravity->g;
  read_status(dir / "summary.json", run);
  run.rest = io::read_obj((dir / "rest.obj").string());

  const std::vector<fs::path> files = run.dynamic ? frame_files(dir / "frames") : std::vector<fs::path>{};
  const double frame_interval = scene.solve.dt * scene.output_every;
  for (std::size_t i = 0; i < files.size(); ++i)
    run.frames.push_back(read_frame(files[i], static_cast<double>(i) * frame_interval, run.rest));
  const fs::path final_obj = dir / "final.obj";
  if (fs::is_regular_file(final_obj)) {
    Frame last = read_frame(final_obj, run.dynamic ? scene.solve.dt * scene.solve.steps : 0.0, run.rest);
    if (run.frames.empty() || last.vertices != run.frames.back().vertices) run.frames.push_back(std::move(last));
  }
  if (run.frames.empty() && run.dynamic) not_an_output_folder(folder, "no frames/ and no final.obj");
  if (run.frames.empty())
    throw InputError(folder + ": nothing to show: a static run that failed writes no final.obj (summary.json: " +
                     (run.reason.empty() ? run.status : run.reason) + ")");
  return run;
}

}  // namespace hinge::view
