// hinge/view/run.hpp: a simulation's output folder (docs/contract.md, `hinge simulate`'s outputs) read for
// `hinge view`: the resolved scene (scene.json), the rest shape (rest.obj), summary.json's status, and the
// states to show with their times (frames/NNNNN.obj in order, then final.obj where it adds a state).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hinge/core/mesh.hpp"
#include "hinge/io/scene.hpp"

namespace hinge::view {

// One state of the run: its vertex positions (the rest shape's faces) at time `time`.
struct Frame {
  std::string file;  // the OBJ it was read from, for messages
  double time = 0;   // s from the start of the run; 0 for a static solve
  std::vector<std::array<double, 3>> vertices;
};

struct Run {
  std::string folder;
  std::string name;  // the scene's
  bool dynamic = false;
  std::string status;  // summary.json's "ok" or "failed"
  std::string reason;  // a failed run's reason, else empty
  Mesh rest;           // rest.obj
  std::vector<Frame> frames;
  std::optional<io::Sphere> sphere;
  std::optional<io::Vec3> gravity;  // the scene's g, to hold the view upright
};

// Reads the output folder `folder` of `hinge simulate`. The frames: a dynamic run's frames/00000.obj,
// 00001.obj, ... (frame i at time i * output.every * dt), then final.obj at steps * dt when it differs from
// the last frame; a static run's final.obj alone. A failed run has no final.obj: its frames are shown.
// Throws hinge::InputError naming the folder when it is not a simulation's output folder (no summary.json,
// scene.json or rest.obj; a dynamic run without frames; a frame missing from the sequence) or has nothing to
// show (a static run that failed: no final.obj), naming the file for a file that cannot be read, and naming
// the frame for a frame whose vertex count or faces differ from rest.obj's.
Run read_run(const std::string& folder);

}  // namespace hinge::view
