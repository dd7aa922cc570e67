// Reading a scene file strictly (hinge/io/scene.hpp).
#include "hinge/io/scene.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string_view>

#include "hinge/core/bending_problem.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/core/method.hpp"
#include "hinge/core/samples.hpp"
#include "hinge/core/scalar.hpp"
#include "hinge/io/obj.hpp"

namespace hinge::io {

namespace {

using json = nlohmann::json;

// A JSON object being read: every key must be taken (required or optional) before done(), which names any
// key left over. Messages: "FILE: KEY: why".
class Object {
 public:
  Object(const std::string& file, const json& value, std::string path)
      : file_(file), value_(value), path_(std::move(path)) {
    if (!value_.is_object()) fail(path_.empty() ? "the scene must be a JSON object" : "expected an object");
  }

  [[noreturn]] void fail(const std::string& why) const { fail_at(path_, why); }
  [[noreturn]] void fail_at(const std::string& key, const std::string& why) const {
    throw InputError(file_ + ": " + (key.empty() ? std::string() : key + ": ") + why);
  }
  std::string key_path(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  // The bending problem's checks (hinge/core/bending_problem.hpp) on `key`, named by its path: "FILE: KEY: why",
  // the sentence the command line and Python say with their own name for the parameter.
  template <class Check>
  auto checked(Check&& check) const {
    try {
      return check();
    } catch (const ParameterError& e) {
      throw InputError(file_ + ": " + e.what());
    }
  }
  // A name parsed by `parse` (std::invalid_argument naming what it expects): "FILE: KEY: why".
  template <class Parse>
  auto parsed(const std::string& key, Parse&& parse) {
    const std::string value = string(key);
    try {
      return parse(value);
    } catch (const std::invalid_argument& e) {
      fail_at(key_path(key), e.what());
    }
  }
  double checked_number(const std::string& key, double (*check)(Parameter)) {
    const double value = number(key);
    const std::string path = key_path(key);
    return checked([&] { return check({value, path}); });
  }

  bool has(const std::string& key) const { return value_.contains(key); }
  const json* optional(const std::string& key) {
    taken_.insert(key);
    const auto it = value_.find(key);
    return it == value_.end() ? nullptr : &*it;
  }
  const json& required(const std::string& key) {
    const json* v = optional(key);
    if (!v) fail_at(key_path(key), "required key missing");
    return *v;
  }
  Object object(const std::string& key) { return Object(file_, required(key), key_path(key)); }

  double number(const std::string& key, const json& v) const {
    if (!v.is_number()) fail_at(key_path(key), "expected a number, got " + v.dump());
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail_at(key_path(key), "expected a finite number");
    return x;
  }
  double number(const std::string& key) { return number(key, required(key)); }
  double positive(const std::string& key) {
    const double x = number(key);
    if (!(x > 0)) fail_at(key_path(key), "expected a positive number, got " + required(key).dump());
    return x;
  }
  std::optional<double> optional_number(const std::string& key) {
    const json* v = optional(key);
    if (!v) return std::nullopt;
    return number(key, *v);
  }
  long long integer(const std::string& key, const json& v) const {
    if (!v.is_number_integer()) fail_at(key_path(key), "expected an integer, got " + v.dump());
    return v.get<long long>();
  }
  std::string string(const std::string& key) {
    const json& v = required(key);
    if (!v.is_string()) fail_at(key_path(key), "expected a string, got " + v.dump());
    return v.get<std::string>();
  }
  std::string choice(const std::string& key, std::initializer_list<std::string_view> allowed) {
    const std::string s = string(key);
    std::string list;
    for (auto a : allowed) {
      if (s == a) return s;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    fail_at(key_path(key), "unknown value '" + s + "' (expected one of " + list + ")");
  }
  Vec3 vec3(const std::string& key) {
    const json& v = required(key);
    if (!v.is_array() || v.size() != 3) fail_at(key_path(key), "expected an array of 3 numbers, got " + v.dump());
    return {number(key, v[0]), number(key, v[1]), number(key, v[2])};
  }
  std::vector<Index> vertex_list(const std::string& key, std::size_t vertex_count) {
    const json& v = required(key);
    if (!v.is_array()) fail_at(key_path(key), "expected an array of vertex indices, got " + v.dump());
    std::vector<Index> out;
    std::set<Index> seen;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string at = key + "[" + std::to_string(i) + "]";
      const long long j = integer(at, v[i]);
      if (j < 0 || static_cast<std::size_t>(j) >= vertex_count)
        fail_at(key_path(at), "vertex " + std::to_string(j) + " out of range (the mesh has " +
                                  std::to_string(vertex_count) + " vertices, numbered from 0)");
      if (!seen.insert(static_cast<Index>(j)).second)
        fail_at(key_path(at), "vertex " + std::to_string(j) + " listed twice");
      out.push_back(static_cast<Index>(j));
    }
    return out;
  }

  // The keys the format knows here: any other is an error naming it, before anything else is checked.
  void allow(std::initializer_list<const char*> known) const {
    for (const auto& [key, v] : value_.items()) {
      bool found = false;
      for (const char* k : known) found = found || key == k;
      if (!found) {
        std::string list;
        for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
        fail_at(key_path(key), "unknown key (expected one of " + list + ")");
      }
    }
  }

  // Every key of the object must have been taken.
  void done() const {
    for (const auto& [key, v] : value_.items())
      if (!taken_.count(key)) fail_at(key_path(key), "unknown key");
  }

 private:
  const std::string& file_;
  const json& value_;
  std::string path_;
  std::set<std::string> taken_;
};

// The OBJ file named by `key` of `o`, relative to the scene's folder; its errors name the scene and the key.
Mesh read_mesh_file(Object& o, const std::string& key, const std::filesystem::path& folder) {
  const std::string name = o.string(key);
  try {
    return read_obj((folder / name).string());
  } catch (const InputError& e) {
    o.fail_at(o.key_path(key), e.what());
  }
}

Mesh read_mesh_object(Object& mesh, const std::filesystem::path& folder, Scene& s) {
  Mesh m;
  const bool obj = mesh.has("obj"), grid = mesh.has("grid");
  if (obj == grid) mesh.fail("exactly one of \"obj\" and \"grid\" is required");
  if (obj) {
    m = read_mesh_file(mesh, "obj", folder);
    s.mesh_obj = (folder / mesh.string("obj")).string();
  } else {
    Object g = mesh.object("grid");
    g.allow({"vertices", "size", "center", "plane"});
    const json& n = g.required("vertices");
    if (!n.is_array() || n.size() != 2) g.fail_at(g.key_path("vertices"), "expected [nx, ny], got " + n.dump());
    const long long nx = g.integer("vertices", n[0]), ny = g.integer("vertices", n[1]);
    if (nx < 2 || ny < 2 || nx > 100000 || ny > 100000 || nx * ny > 50'000'000)
      g.fail_at(g.key_path("vertices"), "expected 2 <= nx, ny and nx ny <= 5e7, got " + n.dump());
    const json& size = g.required("size");
    if (!size.is_array() || size.size() != 2) g.fail_at(g.key_path("size"), "expected [lx, ly], got " + size.dump());
    const double lx = g.number("size", size[0]), ly = g.number("size", size[1]);
    if (!(lx > 0 && ly > 0)) g.fail_at(g.key_path("size"), "expected positive sizes, got " + size.dump());
    const Vec3 center = g.vec3("center");
    const std::string plane = g.choice("plane", {"xy", "xz", "yz"});
    g.done();
    s.grid = Grid{static_cast<int>(nx), static_cast<int>(ny), lx, ly, center, plane};
    m = grid_mesh(static_cast<int>(nx), static_cast<int>(ny), lx, ly, center, plane);
  }
  if (mesh.has("velocity")) s.velocity = mesh.vec3("velocity");
  return m;
}

}  // namespace

Scene read_scene(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the scene file");
  return read_scene(in, path, std::filesystem::path(path).parent_path().string());
}

Scene read_scene(std::istream& in, const std::string& path, const std::string& folder_name) {
  json root;
  try {
    root = json::parse(in);
  } catch (const json::parse_error& e) {
    throw InputError(path + ": not valid JSON: " + e.what());
  }
  Scene s;
  s.file = path;
  const std::filesystem::path folder(folder_name);
  Object top(s.file, root, "");
  top.allow({"scene", "name", "mesh", "material", "solve", "effects", "output"});

  const json& version = top.required("scene");
  if (!version.is_number_integer() || version.get<long long>() != 1)
    top.fail_at("scene", "unsupported format version " + version.dump() + " (this program reads format 1)");
  s.name = top.string("name");

  {
    Object mesh = top.object("mesh");
    mesh.allow({"obj", "grid", "rest", "velocity"});
    s.mesh = read_mesh_object(mesh, folder, s);
    if (const json* r = mesh.optional("rest")) {
      Object rest(s.file, *r, "mesh.rest");
      rest.allow({"obj"});
      s.rest = read_mesh_file(rest, "obj", folder);
      rest.done();
      if (s.rest.vertices.size() != s.mesh.vertices.size() || s.rest.faces != s.mesh.faces)
        mesh.fail_at("mesh.rest", "the rest shape must have the initial mesh's vertex count and faces");
    } else {
      s.rest = s.mesh;
    }
    mesh.optional("obj"), mesh.optional("grid"), mesh.optional("velocity");
    mesh.done();
  }
  const std::size_t n = s.mesh.vertices.size();

  {
    Object m = top.object("material");
    m.allow({"density", "young", "poisson", "thickness"});
    s.material.density = m.positive("density");
    s.material.thickness = m.checked_number("thickness", check_thickness);
    if (m.has("young")) s.material.young = m.checked_number("young", check_young);
    if (m.has("poisson")) s.material.poisson = m.checked_number("poisson", check_poisson);
    m.done();
  }

  {
    Object solve = top.object("solve");
    solve.allow(
        {"mode", "dt", "steps", "residual_tolerance", "newton_tolerance", "max_newton", "hessian", "linear_solver"});
    const std::string mode = solve.choice("mode", {"static", "dynamic"});
    s.solve.mode = mode == "static" ? Mode::static_equilibrium : Mode::dynamic;
    if (s.solve.mode == Mode::dynamic) {
      s.solve.dt = solve.positive("dt");
      const long long steps = solve.integer("steps", solve.required("steps"));
      if (steps < 1 || steps > 100'000'000) solve.fail_at("solve.steps", "expected an integer in [1, 1e8]");
      s.solve.steps = static_cast<int>(steps);
    } else {
      for (const char* key : {"dt", "steps"})
        if (solve.has(key)) solve.fail_at(solve.key_path(key), "not allowed with \"mode\": \"static\"");
      if (root["mesh"].contains("velocity"))
        solve.fail_at("mesh.velocity", "not allowed with \"mode\": \"static\" (an equilibrium has no velocity)");
    }
    if (solve.has("residual_tolerance")) s.solve.residual_tolerance = solve.positive("residual_tolerance");
    if (solve.has("newton_tolerance")) s.solve.newton_tolerance = solve.positive("newton_tolerance");
    if (const json* v = solve.optional("max_newton")) {
      const long long k = solve.integer("max_newton", *v);
      if (k < 1 || k > 1'000'000) solve.fail_at("solve.max_newton", "expected an integer in [1, 1e6]");
      s.solve.max_newton = static_cast<int>(k);
    }
    if (solve.has("hessian")) {
      const std::string h = solve.choice("hessian", {"exact", "projected", "gauss-newton"});
      s.solve.hessian = h == "exact"       ? HessianTreatment::exact
                        : h == "projected" ? HessianTreatment::projected
                                           : HessianTreatment::gauss_newton;
    }
    if (solve.has("linear_solver"))
      s.solve.linear_solver =
          solve.choice("linear_solver", {"cholmod", "ldlt"}) == "cholmod" ? LinearSolver::cholmod : LinearSolver::ldlt;
    solve.done();
  }

  if (top.has("effects")) {
    Object fx = top.object("effects");
    fx.allow({"gravity", "stretching", "bending", "damping", "pins", "sphere", "load"});
    if (fx.has("gravity")) {
      Object e = fx.object("gravity");
      e.allow({"g"});
      s.gravity = Gravity{e.vec3("g")};
      e.done();
    }
    if (fx.has("stretching")) {
      Object e = fx.object("stretching");
      e.allow({"model"});
      e.choice("model", {"stvk"});
      e.done();
      if (!(s.material.young > 0)) fx.fail_at("material.young", "required by effects.stretching");
      s.stretching = Stretching{};
    }
    if (fx.has("bending")) {
      Object e = fx.object("bending");
      e.allow({"energy", "k", "method", "scalar"});
      Bending b;
      const std::string energy = e.string("energy"), energy_path = e.key_path("energy");
      b.energy = e.checked([&] { return parse_bending_energy(energy, energy_path); });
      if (e.has("k")) {
        b.k = e.checked_number("k", check_k);
      } else {
        if (!(s.material.young > 0))
          fx.fail_at("material.young", "required by effects.bending without \"k\" (eq. (11))");
        b.k = e.checked([&] {
          return stiffness_from_material({s.material.young, "material.young"}, {s.material.poisson, "material.poisson"},
                                         {s.material.thickness, "material.thickness"});
        });
      }
      if (e.has("method")) b.method = e.parsed("method", parse_method);
      if (e.has("scalar")) b.scalar = e.parsed("scalar", parse_scalar_type);
      e.done();
      s.bending = b;
    }
    if (fx.has("damping")) {
      Object e = fx.object("damping");
      e.allow({"model", "mass", "bending"});
      e.choice("model", {"viscous"});
      Damping d;
      if (e.has("mass")) {
        d.mass = e.number("mass");
        if (!(d.mass >= 0)) e.fail_at("effects.damping.mass", "expected a number >= 0");
      }
      if (e.has("bending")) {
        d.bending = e.number("bending");
        if (!(d.bending >= 0)) e.fail_at("effects.damping.bending", "expected a number >= 0");
      }
      e.done();
      if (!(d.mass > 0 || d.bending > 0)) fx.fail_at("effects.damping", "needs \"mass\" or \"bending\" above 0");
      if (s.solve.mode != Mode::dynamic)
        fx.fail_at("effects.damping", "only with \"mode\": \"dynamic\" (a static solve has no velocity)");
      if (d.bending > 0) {
        if (!s.bending || s.bending->energy != Model::tan)
          fx.fail_at("effects.damping.bending",
                     "needs effects.bending with \"energy\": \"tan\" (the paper's section 5 is written for it)");
        if (s.solve.hessian == HessianTreatment::exact &&
            (s.bending->method != Method::fast || s.bending->scalar.kind != ScalarType::Kind::kind_double))
          fx.fail_at("effects.damping.bending", "with \"hessian\": \"exact\" needs the bending method fast in double");
      }
      s.damping = d;
    }
    if (fx.has("pins")) {
      Object e = fx.object("pins");
      e.allow({"vertices"});
      s.pins = Pins{e.vertex_list("vertices", n)};
      e.done();
    }
    if (fx.has("sphere")) {
      Object e = fx.object("sphere");
      e.allow({"center", "radius"});
      Sphere sp;
      sp.center = e.vec3("center");
      sp.radius = e.positive("radius");
      e.done();
      s.sphere = sp;
    }
    if (fx.has("load")) {
      Object e = fx.object("load");
      e.allow({"vertices", "force"});
      Load l;
      l.vertices = e.vertex_list("vertices", n);
      l.force = e.vec3("force");
      e.done();
      s.load = l;
    }
  }

  if (top.has("output")) {
    Object o = top.object("output");
    o.allow({"every"});
    if (const json* v = o.optional("every")) {
      const long long every = o.integer("every", *v);
      if (every < 1) o.fail_at("output.every", "expected an integer >= 1");
      s.output_every = static_cast<int>(std::min<long long>(every, 1'000'000'000));
    }
    o.done();
  }
  if (s.solve.mode == Mode::dynamic && s.solve.steps / s.output_every >= 100000)
    top.fail_at("output.every", "the run would write " + std::to_string(s.solve.steps / s.output_every + 1) +
                                    " frames; frames are numbered with five digits (at most 100000)");
  top.optional("effects"), top.optional("output");
  top.done();
  return s;
}

std::string resolved_scene_json(const Scene& s, const std::string& out_dir) {
  namespace fs = std::filesystem;
  nlohmann::ordered_json j;  // numbers as the shortest decimal that reads back exactly
  j["scene"] = 1;
  j["name"] = s.name;
  auto& mesh = j["mesh"];
  if (s.grid) {
    mesh["grid"] = {{"vertices", {s.grid->nx, s.grid->ny}},
                    {"size", {s.grid->lx, s.grid->ly}},
                    {"center", s.grid->center},
                    {"plane", s.grid->plane}};
  } else {
    mesh["obj"] = fs::relative(fs::absolute(s.mesh_obj), fs::absolute(out_dir)).generic_string();
  }
  mesh["rest"] = {{"obj", "rest.obj"}};
  if (s.solve.mode == Mode::dynamic) mesh["velocity"] = s.velocity;
  auto& m = j["material"];
  m["density"] = s.material.density;
  if (s.material.young > 0) m["young"] = s.material.young;  // none: no effect needs it
  m["poisson"] = s.material.poisson;
  m["thickness"] = s.material.thickness;
  auto& solve = j["solve"];
  solve["mode"] = s.solve.mode == Mode::dynamic ? "dynamic" : "static";
  if (s.solve.mode == Mode::dynamic) solve["dt"] = s.solve.dt, solve["steps"] = s.solve.steps;
  solve["residual_tolerance"] = s.solve.residual_tolerance;
  solve["newton_tolerance"] = s.solve.newton_tolerance;
  solve["max_newton"] = s.solve.max_newton;
  solve["hessian"] = s.solve.hessian == HessianTreatment::exact       ? "exact"
                     : s.solve.hessian == HessianTreatment::projected ? "projected"
                                                                      : "gauss-newton";
  solve["linear_solver"] = s.solve.linear_solver == LinearSolver::cholmod ? "cholmod" : "ldlt";
  auto fx = nlohmann::ordered_json::object();
  if (s.gravity) fx["gravity"] = {{"g", s.gravity->g}};
  if (s.stretching) fx["stretching"] = {{"model", "stvk"}};
  if (s.bending)
    fx["bending"] = {{"energy", std::string(model_name(s.bending->energy))},
                     {"k", s.bending->k},
                     {"method", std::string(method_name(s.bending->method))},
                     {"scalar", s.bending->scalar.name()}};
  if (s.damping) fx["damping"] = {{"model", "viscous"}, {"mass", s.damping->mass}, {"bending", s.damping->bending}};
  if (s.pins) fx["pins"] = {{"vertices", s.pins->vertices}};
  if (s.sphere) fx["sphere"] = {{"center", s.sphere->center}, {"radius", s.sphere->radius}};
  if (s.load) fx["load"] = {{"vertices", s.load->vertices}, {"force", s.load->force}};
  j["effects"] = fx;
  j["output"] = {{"every", s.output_every}};
  return j.dump(2) + "\n";
}

}  // namespace hinge::io
