// Scene files are read strictly: a key the format does not know, anywhere, or a bad value is an error
// naming the file and the key (the contract's "hinge simulate and scene files").
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hinge/core/errors.hpp"
#include "hinge/io/scene.hpp"

namespace hinge::io {
namespace {

// A scene file written into a fresh folder under the system's temporary directory, one per process and
// test (ctest runs this file's tests side by side, each in its own process).
std::filesystem::path write_scene(const std::string& name, const std::string& json) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const auto dir = std::filesystem::temp_directory_path() /
                   ("hinge-io-scene-test-" + std::to_string(::getpid()) + "-" + test + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "scene.json") << json;
  return dir / "scene.json";
}

const std::string kValid = R"({"scene": 1, "name": "t",
 "mesh": {"grid": {"vertices": [3, 2], "size": [2, 1], "center": [0, 0, 1], "plane": "xz"}},
 "material": {"density": 1000, "young": 1e6, "poisson": 0.25, "thickness": 0.01},
 "solve": {"mode": "dynamic", "dt": 0.01, "steps": 3},
 "effects": {"gravity": {"g": [0, 0, -9.81]}, "pins": {"vertices": [0, 2]}},
 "output": {"every": 1}})";

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

// The message of the InputError that reading `json` raises ("" if none).
std::string error_of(const std::string& json) {
  const auto path = write_scene("scene", json);
  try {
    read_scene(path.string());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Scene, AValidSceneReadsWithExactlyTheEffectsItNames) {
  const Scene s = read_scene(write_scene("valid", kValid).string());
  EXPECT_TRUE(s.gravity && s.pins);
  EXPECT_FALSE(s.stretching || s.bending || s.damping || s.sphere || s.load);
  EXPECT_EQ(s.solve.mode, Mode::dynamic);
  EXPECT_EQ(s.solve.hessian, HessianTreatment::projected);  // the contract's defaults
  EXPECT_EQ(s.solve.linear_solver, LinearSolver::cholmod);
  EXPECT_EQ(s.solve.max_newton, 100);
  EXPECT_EQ(s.solve.newton_tolerance, 1e-9);
}

TEST(Scene, GridFollowsTheContract) {
  const Scene s = read_scene(write_scene("grid", kValid).string());
  ASSERT_EQ(s.mesh.vertices.size(), 6u);
  // vertex i + nx j at center + (i/(nx-1) - 1/2) lx a + (j/(ny-1) - 1/2) ly b, plane xz: a = x, b = z
  EXPECT_EQ(s.mesh.vertices[0], (Vec3{-1, 0, 0.5}));
  EXPECT_EQ(s.mesh.vertices[4], (Vec3{0, 0, 1.5}));
  ASSERT_EQ(s.mesh.faces.size(), 4u);
  EXPECT_EQ(s.mesh.faces[0], (std::array<Index, 3>{0, 1, 4}));  // (p, q, r), p = (0,0), r = (1,1)
  EXPECT_EQ(s.mesh.faces[1], (std::array<Index, 3>{0, 4, 3}));  // (p, r, s)
}

TEST(Scene, AnUnknownKeyAnywhereIsAnErrorNamingIt) {
  EXPECT_NE(error_of(replaced(kValid, "\"gravity\"", "\"gravty\"")).find("effects.gravty: unknown key"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(kValid, "\"dt\"", "\"dtt\"")).find("solve.dtt"), std::string::npos);
  EXPECT_NE(error_of(replaced(kValid, "\"g\"", "\"G\"")).find("effects.gravity.G"), std::string::npos);
  EXPECT_NE(error_of(replaced(kValid, "\"plane\"", "\"plane\": \"xz\", \"sise\"")).find("mesh.grid.sise: unknown key"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(kValid, "\"every\"", "\"evry\"")).find("output.evry"), std::string::npos);
  EXPECT_NE(error_of(replaced(kValid, "\"name\"", "\"nam\"")).find("nam: unknown key (expected one of scene, name,"),
            std::string::npos);
  EXPECT_NE(error_of(replaced(kValid, "\"name\": \"t\",", "\"name\": \"t\", \"extra\": 1,")).find("extra: unknown key"),
            std::string::npos);
}

TEST(Scene, BadValuesAreErrorsNamingTheKey) {
  const auto has = [](const std::string& json, const std::string& what) {
    const std::string e = error_of(json);
    EXPECT_NE(e.find("scene.json"), std::string::npos) << e;  // the file
    EXPECT_NE(e.find(what), std::string::npos) << e;
  };
  has(replaced(kValid, "\"density\": 1000", "\"density\": -1"), "material.density");
  has(replaced(kValid, "\"poisson\": 0.25", "\"poisson\": 0.7"),
      "material.poisson: Poisson's ratio nu must be in (-1, 0.5], got 0.7");
  has(replaced(kValid, "[0, 2]", "[0, 6]"), "effects.pins.vertices[1]: vertex 6 out of range");
  has(replaced(kValid, "[0, 2]", "[0, 0]"), "listed twice");
  has(replaced(kValid, "\"dynamic\"", "\"static\""), "solve.dt: not allowed");
  has(replaced(kValid, "\"dynamic\"", "\"dynamc\""), "solve.mode: unknown value 'dynamc'");
  has(replaced(kValid, "\"steps\": 3", "\"steps\": 2.5"), "solve.steps: expected an integer");
  has(replaced(kValid, "\"pins\"", "\"bending\": {\"energy\": \"tann\"}, \"pins\""), "effects.bending.energy");
  has(replaced(kValid, "\"pins\"", "\"bending\": {\"energy\": \"tan\", \"method\": \"fastest\"}, \"pins\""),
      "effects.bending.method");
  has(replaced(kValid, "\"pins\"", "\"damping\": {\"model\": \"viscous\", \"bending\": 0.1}, \"pins\""),
      "effects.damping.bending: needs effects.bending");
  has(replaced(kValid, "\"scene\": 1", "\"scene\": 2"), "unsupported format version 2");
  has(replaced(kValid, "[3, 2]", "[1, 2]"), "mesh.grid.vertices");
  has(replaced(kValid, "{\"grid\"", "{\"obj\": \"missing.obj\", \"grid\""), "exactly one of");
  has(replaced(kValid, "\"t\",", "\"t\""), "not valid JSON");
}

// What `hinge simulate` writes as DIR/scene.json: read back from DIR (with DIR/rest.obj written there) it is
// the same scene, every default filled in, the mesh's OBJ path relative to DIR.
TEST(Scene, TheResolvedSceneReadsBackTheSameFromTheOutputFolder) {
  const auto file = write_scene("resolved", "");
  const auto folder = file.parent_path();
  std::ofstream(folder / "quad.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
  std::ofstream(file) << R"({"scene": 1, "name": "r", "mesh": {"obj": "quad.obj", "velocity": [0, 0, -1]},
 "material": {"density": 10, "young": 1e6, "poisson": 0.3, "thickness": 0.01},
 "solve": {"mode": "dynamic", "dt": 0.01, "steps": 3, "residual_tolerance": 1e-9},
 "effects": {"gravity": {"g": [0, 0, -9.81]}, "stretching": {"model": "stvk"}, "bending": {"energy": "tan"},
             "damping": {"model": "viscous", "mass": 0.5}, "pins": {"vertices": [0]},
             "sphere": {"center": [0, 0, -1], "radius": 0.5}, "load": {"vertices": [2], "force": [0, 1, 0]}}})";
  const Scene s = read_scene(file.string());
  const auto out = folder / "run" / "out";
  std::filesystem::create_directories(out);
  const std::string resolved = resolved_scene_json(s, out.string());
  EXPECT_NE(resolved.find("\"../../quad.obj\""), std::string::npos) << resolved;
  std::ofstream(out / "scene.json") << resolved;
  std::ofstream(out / "rest.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
  const Scene t = read_scene((out / "scene.json").string());
  EXPECT_EQ(resolved_scene_json(t, out.string()), resolved);
  EXPECT_EQ(t.mesh.vertices, s.mesh.vertices);
  EXPECT_EQ(t.bending->k, s.bending->k);  // eq. (11)'s value, written exactly
  EXPECT_EQ(t.solve.residual_tolerance, 1e-9);
  EXPECT_EQ(t.solve.newton_tolerance, 1e-9);  // the default, filled in
  EXPECT_EQ(t.solve.max_newton, 100);
  EXPECT_EQ(t.velocity, s.velocity);
  EXPECT_EQ(t.damping->mass, 0.5);
  EXPECT_EQ(t.load->vertices, s.load->vertices);
}

}  // namespace
}  // namespace hinge::io
