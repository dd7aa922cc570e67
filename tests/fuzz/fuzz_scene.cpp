// Fuzz target: the scene reader (hinge/io/scene.hpp), meshes relative to a folder that holds none (so a
// scene that names an OBJ file fails as a missing file; grids are built). On success the scene is one
// the simulator can start: a mesh with faces, a rest shape of the same topology, positive material
// constants and tolerances, a time step and step count for a dynamic solve, pins and loads on vertices
// of the mesh, and its resolved form (what `hinge simulate` writes as scene.json) reads back the same.
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fuzz_target.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using hinge::fuzz::require;
  std::istringstream in(hinge::fuzz::as_string(data, size));
  const std::string folder = "/nonexistent-hinge-fuzz-folder";
  try {
    const hinge::io::Scene s = hinge::io::read_scene(in, "fuzz-scene.json", folder);
    require(!s.mesh.faces.empty(), "a scene without faces was accepted");
    require(s.rest.faces == s.mesh.faces && s.rest.vertices.size() == s.mesh.vertices.size(),
            "a rest shape of another topology was accepted");
    require(s.material.density > 0 && s.material.thickness > 0, "a non-positive density or thickness");
    require(s.solve.residual_tolerance > 0 && s.solve.newton_tolerance > 0 && s.solve.max_newton >= 1,
            "a non-positive tolerance");
    if (s.solve.mode == hinge::io::Mode::dynamic)
      require(s.solve.dt > 0 && std::isfinite(s.solve.dt) && s.solve.steps >= 1, "a dynamic solve without dt or steps");
    const auto n = static_cast<long long>(s.mesh.vertices.size());
    if (s.pins)
      for (auto v : s.pins->vertices) require(v >= 0 && v < n, "a pin outside the mesh");
    if (s.load)
      for (auto v : s.load->vertices) require(v >= 0 && v < n, "a load outside the mesh");
    if (s.grid) {  // a grid scene's resolved form names no file but rest.obj: read it back without that key
      auto resolved = nlohmann::json::parse(hinge::io::resolved_scene_json(s, folder));
      require(resolved["mesh"]["rest"] == nlohmann::json{{"obj", "rest.obj"}},
              "the resolved scene does not name rest.obj");
      resolved["mesh"].erase("rest");
      std::istringstream again(resolved.dump());
      const hinge::io::Scene t = hinge::io::read_scene(again, "resolved.json", folder);
      require(t.mesh.vertices == s.mesh.vertices && t.mesh.faces == s.mesh.faces, "the resolved grid differs");
      require(hinge::io::resolved_scene_json(t, folder) == hinge::io::resolved_scene_json(s, folder),
              "the resolved scene does not read back the same");
    }
  } catch (const hinge::InputError&) {
  }
  return 0;
}
