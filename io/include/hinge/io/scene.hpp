// hinge/io/scene.hpp: a scene file (docs/simulator.md; the contract's "hinge simulate and scene files",
// format 1) read into memory, checked strictly: a key the format does not know, anywhere, a missing
// required key, a value of the wrong type or out of range, a pin or load vertex out of range, are
// hinge::InputError "FILE: KEY: why", KEY the key's path (`effects.gravity.g`). Nothing here simulates.
#pragma once

#include <array>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "hinge/core/energy.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/core/method.hpp"
#include "hinge/core/scalar.hpp"

namespace hinge::io {

using Vec3 = std::array<double, 3>;

struct Material {
  double density = 0;    // kg/m^3
  double young = 0;      // Pa (needed by stretching, and by bending without "k")
  double poisson = 0;    // in (-1, 1/2]
  double thickness = 0;  // m
};

enum class Mode { static_equilibrium, dynamic };
// How an indefinite Hessian is treated in Newton's linear systems (docs/simulator.md, "Newton").
enum class HessianTreatment { exact, projected, gauss_newton };
enum class LinearSolver { cholmod, ldlt };

struct Solve {
  Mode mode = Mode::static_equilibrium;
  double dt = 0;  // dynamic only
  int steps = 0;  // dynamic only
  // Newton's stop rule (docs/simulator.md, "When Newton stops"): the largest force residual on a free vertex
  // at most residual_tolerance times the scene's force scale, and (on the newton and projected rungs) the
  // step moving no vertex more than newton_tolerance times the longest rest edge.
  double residual_tolerance = 1e-8;
  double newton_tolerance = 1e-9;
  int max_newton = 100;
  HessianTreatment hessian = HessianTreatment::projected;
  LinearSolver linear_solver = LinearSolver::cholmod;
};

// The effects: each present only when the scene names it.
struct Gravity {
  Vec3 g{};
};
struct Stretching {};  // "model": "stvk", the only model
struct Bending {
  Model energy = Model::shells;
  double k = 0;                  // given, or eq. (11) from the material (hinge/core/bending_problem.hpp)
  Method method = Method::fast;  // hinge eval's methods and scalar types
  ScalarType scalar{};           // double
};
struct Damping {
  double mass = 0;     // 1/s: the drag force -mass M v
  double bending = 0;  // s: the paper's k_d = bending * k (section 5), tan energy only
};
struct Pins {
  std::vector<Index> vertices;
};
struct Sphere {
  Vec3 center{};
  double radius = 0;
};
struct Load {
  std::vector<Index> vertices;
  Vec3 force{};
};

// The initial mesh's "grid" (the contract's grid mesh, hinge/core/samples.hpp).
struct Grid {
  int nx = 0, ny = 0;
  double lx = 0, ly = 0;
  Vec3 center{};
  std::string plane;
};

struct Scene {
  std::string file;  // the scene file, for messages
  std::string name;
  std::string mesh_obj;      // the initial mesh's OBJ file (the scene's folder joined to "obj"), or
  std::optional<Grid> grid;  // its grid
  Mesh mesh;                 // the initial state (from "obj" or "grid")
  Mesh rest;                 // the rest shape: "rest", else the initial mesh
  Vec3 velocity{};
  Material material;
  Solve solve;
  std::optional<Gravity> gravity;
  std::optional<Stretching> stretching;
  std::optional<Bending> bending;
  std::optional<Damping> damping;
  std::optional<Pins> pins;
  std::optional<Sphere> sphere;
  std::optional<Load> load;
  int output_every = 1;  // frames every this many steps (dynamic)
};

// Reads and checks the scene file at `path`; its meshes are read relative to its folder (a grid is
// hinge::grid_mesh of hinge/core/samples.hpp).
Scene read_scene(const std::string& path);
// The same from a stream: `name` for messages, meshes read relative to `folder`.
Scene read_scene(std::istream& in, const std::string& name, const std::string& folder);

// The scene as resolved (`hinge simulate` writes it as DIR/scene.json): a valid scene file with every
// default filled in (bending's k as eq. (11) gave it), its initial mesh's OBJ path relative to `out_dir`
// (a grid stays a grid), its rest shape {"obj": "rest.obj"} (the caller writes the rest shape there).
// Read back from out_dir it gives the same scene.
std::string resolved_scene_json(const Scene& scene, const std::string& out_dir);

}  // namespace hinge::io
