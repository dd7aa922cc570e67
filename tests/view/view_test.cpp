// hinge::view: base64 is RFC 4648's; positions decode within half a quantization level and values to their
// level; each hinge's |theta - theta_bar| is the fold's angle and NaN where the hinge cannot be evaluated; an
// output folder's frames are read in order with their times, final.obj added only where it adds a state;
// folders that are not a run's output, and frames that do not fit, are refused naming the folder or frame;
// the page's data decodes back to the run.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <sstream>
#include <unistd.h>

#include "hinge/core/errors.hpp"
#include "hinge/core/samples.hpp"
#include "hinge/io/obj.hpp"
#include "hinge/view/bending.hpp"
#include "hinge/view/encoding.hpp"
#include "hinge/view/page.hpp"
#include "hinge/view/run.hpp"

namespace hinge::view {
namespace {

namespace fs = std::filesystem;
constexpr double u = std::numeric_limits<double>::epsilon() / 2;

std::vector<std::uint8_t> bytes_of(const std::string& s) { return {s.begin(), s.end()}; }

TEST(Encoding, Base64IsRfc4648sTestVectors) {
  const std::vector<std::pair<std::string, std::string>> vectors = {{"", ""},
                                                                    {"f", "Zg=="},
                                                                    {"fo", "Zm8="},
                                                                    {"foo", "Zm9v"},
                                                                    {"foob", "Zm9vYg=="},
                                                                    {"fooba", "Zm9vYmE="},
                                                                    {"foobar", "Zm9vYmFy"}};
  for (const auto& [text, encoded] : vectors) EXPECT_EQ(base64(bytes_of(text)), encoded) << text;
  EXPECT_EQ(base64(std::vector<std::uint8_t>{0xff, 0xfe, 0xfd}), "//79");
}

TEST(Encoding, Base64OfWiderIntegersIsOfTheirLittleEndianBytes) {
  EXPECT_EQ(base64(std::vector<std::uint16_t>{0x0102}), base64(std::vector<std::uint8_t>{0x02, 0x01}));
  EXPECT_EQ(base64(std::vector<std::int32_t>{-1, 0x01020304}),
            base64(std::vector<std::uint8_t>{0xff, 0xff, 0xff, 0xff, 0x04, 0x03, 0x02, 0x01}));
}

// Decoded positions lie within half a level of the originals, (max - min) / 131070 per axis, plus the
// rounding of min + q (max - min) / 65535: a few units of the box's largest magnitude (4 u is generous for
// its three operations).
TEST(Encoding, PositionsDecodeWithinHalfALevel) {
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> x(-3.0, 5.0), z(0.25, 0.2500001);
  std::vector<Vec3> frame(2000);
  for (Vec3& p : frame) p = {x(rng), x(rng), z(rng)};
  const std::vector<std::vector<Vec3>> frames{frame};
  const Box box = bounding_box(frames);
  const std::vector<std::uint16_t> q = quantize_positions(frame, box);
  for (std::size_t v = 0; v < frame.size(); ++v) {
    const Vec3 p = dequantize_position(&q[3 * v], box);
    for (std::size_t c = 0; c < 3; ++c) {
      const double half_level = (box.max[c] - box.min[c]) / (2.0 * (position_levels - 1));
      const double rounding = 4 * u * std::max(std::abs(box.min[c]), std::abs(box.max[c]));
      ASSERT_LE(std::abs(p[c] - frame[v][c]), half_level + rounding) << "vertex " << v << " axis " << c;
    }
  }
}

TEST(Encoding, TheBoxCornersAreTheEndLevelsAndAFlatAxisIsExact) {
  const std::vector<Vec3> frame{{-1, 2, 7}, {3, 2, 9}, {0.5, 2, 8}};
  const std::vector<std::vector<Vec3>> frames{frame};
  const Box box = bounding_box(frames);
  const std::vector<std::uint16_t> q = quantize_positions(frame, box);
  EXPECT_EQ(q[0], 0);
  EXPECT_EQ(q[3], position_levels - 1);
  EXPECT_EQ(q[5], position_levels - 1);
  for (std::size_t v = 0; v < 3; ++v) EXPECT_EQ(dequantize_position(&q[3 * v], box)[1], 2.0);
}

TEST(Encoding, ValuesTakeTheirNearestLevelAndNanIsNoValue) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::uint8_t> q = quantize_values(std::vector<double>{0, 2, 1, 0.5 * 2 / 254, 3, nan}, 2);
  EXPECT_EQ(q, (std::vector<std::uint8_t>{0, 254, 127, 1, 254, no_value}));
}

// A hinge folded by `angle` about its edge x1 x2 (on the x axis); rest flat.
Mesh folded_hinge(double angle) {
  Mesh m;
  m.vertices = {{0.5, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0.5, -std::cos(angle), std::sin(angle)}};
  m.faces = {{0, 1, 2}, {3, 2, 1}};
  return m;
}

// The kernel's theta is within a few units of the exact angle (hinge/fast/hinge_kernel.hpp: worst 2.4 units);
// the fold's own coordinates carry the rounding of cos and sin, a unit each: 8 u |angle| covers both.
TEST(Bending, TheDeviationIsTheFoldAngleAtTheFoldAndZeroAtRest) {
  const Mesh rest = folded_hinge(0);
  const Topology t = build_topology(rest);
  ASSERT_EQ(t.hinges.size(), 1u);
  const std::vector<double> theta_bar = hinge_angles(t, rest.vertices);
  EXPECT_EQ(theta_bar[0], 0.0);
  for (const double angle : {0.3, 1.0, 2.5}) {
    const std::vector<double> d = bending_deviation(hinge_angles(t, folded_hinge(angle).vertices), theta_bar);
    EXPECT_NEAR(d[0], angle, 8 * u * angle) << angle;
    const std::vector<double> back = bending_deviation(theta_bar, hinge_angles(t, folded_hinge(angle).vertices));
    EXPECT_EQ(back[0], d[0]);
  }
}

TEST(Bending, AHingeThatCannotBeEvaluatedIsNanAndTheOthersAreNot) {
  const Mesh grid = grid_mesh(4, 4, 1, 1, {0, 0, 0}, "xy");
  const Topology t = build_topology(grid);
  std::vector<Vec3> state = grid.vertices;
  state[5] = state[4];  // vertex 5 onto vertex 4: the faces holding both have zero area
  const std::vector<double> theta = hinge_angles(t, state);
  std::size_t nan = 0;
  for (std::size_t h = 0; h < theta.size(); ++h) {
    const auto& x = t.hinges[h].x;
    const bool touches = std::find(x.begin(), x.end(), 5) != x.end() || std::find(x.begin(), x.end(), 4) != x.end();
    if (std::isnan(theta[h])) {
      ++nan;
      EXPECT_TRUE(touches) << "hinge " << h;
    }
  }
  EXPECT_GT(nan, 0u);
  EXPECT_LT(nan, theta.size());
}

// An output folder as `hinge simulate` leaves it: a 3 x 3 grid falling, frames every 2 steps of 0.01 s.
class Folder : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("hinge_view_test_" + std::to_string(::getpid()) + "_" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir / "frames");
    write(
        dir / "scene.json",
        R"({"scene": 1, "name": "drop", "mesh": {"grid": {"vertices": [3, 3], "size": [1, 1], "center": [0, 0, 0],)"
        R"( "plane": "xy"}}, "material": {"density": 1, "thickness": 0.001}, "solve": {"mode": "dynamic", "dt": 0.01,)"
        R"( "steps": 5}, "effects": {"gravity": {"g": [0, 0, -9.81]}, "sphere": {"center": [0, 0, -1], "radius": 0.5}},)"
        R"( "output": {"every": 2}})");
    write(dir / "summary.json", R"({"scene": "drop", "status": "ok", "steps": 5})");
    rest = grid_mesh(3, 3, 1, 1, {0, 0, 0}, "xy");
    write_mesh(dir / "rest.obj", rest);
    for (int i = 0; i < 3; ++i) write_mesh(dir / "frames" / frame_name(i), lowered(rest, 0.1 * i));
    write_mesh(dir / "final.obj", lowered(rest, 0.5));
  }
  void TearDown() override { fs::remove_all(dir); }

  static std::string frame_name(int i) {
    char name[16];
    std::snprintf(name, sizeof name, "%05d.obj", i);
    return name;
  }
  static Mesh lowered(Mesh m, double dz) {
    for (auto& v : m.vertices) v[2] -= dz;
    return m;
  }
  static void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }
  static void write_mesh(const fs::path& p, const Mesh& m) {
    std::ofstream out(p);
    io::write_obj(out, m);
  }
  // The scene made a static solve.
  void make_static() const {
    std::string scene;
    std::getline(std::ifstream(dir / "scene.json"), scene, '\0');
    const std::string dynamic = R"("mode": "dynamic", "dt": 0.01, "steps": 5)";
    scene.replace(scene.find(dynamic), dynamic.size(), R"("mode": "static")");
    write(dir / "scene.json", scene);
  }
  // The message of the InputError that read_run throws here ("" if none).
  std::string refusal() const {
    try {
      read_run(dir.string());
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir;
  Mesh rest;
};

TEST_F(Folder, FramesComeInOrderWithTheirTimesThenFinalObj) {
  const view::Run run = read_run(dir.string());
  EXPECT_EQ(run.name, "drop");
  EXPECT_EQ(run.status, "ok");
  EXPECT_TRUE(run.dynamic);
  ASSERT_TRUE(run.sphere);
  EXPECT_EQ(run.sphere->radius, 0.5);
  ASSERT_EQ(run.frames.size(), 4u);
  const std::vector<double> times{0.0, 0.02, 0.04, 0.05};  // frame i at i * every * dt; final.obj at steps * dt
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_DOUBLE_EQ(run.frames[i].time, times[i]) << i;
    EXPECT_EQ(run.frames[i].vertices, lowered(rest, i < 3 ? 0.1 * static_cast<double>(i) : 0.5).vertices) << i;
  }
}

TEST_F(Folder, FinalObjEqualToTheLastFrameIsNotShownTwice) {
  write_mesh(dir / "final.obj", lowered(rest, 0.1 * 2));
  EXPECT_EQ(read_run(dir.string()).frames.size(), 3u);
}

TEST_F(Folder, AFailedRunShowsItsFramesAndItsReason) {
  fs::remove(dir / "final.obj");
  write(dir / "summary.json", R"({"scene": "drop", "status": "failed", "reason": "no decrease"})");
  const view::Run run = read_run(dir.string());
  EXPECT_EQ(run.frames.size(), 3u);
  EXPECT_EQ(run.status, "failed");
  EXPECT_EQ(run.reason, "no decrease");
}

TEST_F(Folder, AStaticRunShowsFinalObjAlone) {
  fs::remove_all(dir / "frames");
  make_static();
  const view::Run run = read_run(dir.string());
  EXPECT_FALSE(run.dynamic);
  ASSERT_EQ(run.frames.size(), 1u);
  EXPECT_EQ(run.frames[0].time, 0.0);
}

TEST_F(Folder, AFolderWithoutSceneJsonIsRefusedNamingTheFolder) {
  fs::remove(dir / "scene.json");
  const std::string why = refusal();
  EXPECT_NE(why.find(dir.string() + ": not a simulation's output folder"), std::string::npos) << why;
  EXPECT_NE(why.find("scene.json"), std::string::npos) << why;
}

TEST_F(Folder, AMissingFolderAndOneWithNothingToShowAreRefused) {
  fs::remove_all(dir / "frames");
  fs::remove(dir / "final.obj");
  EXPECT_NE(refusal().find(dir.string() + ": not a simulation's output folder (no frames/ and no final.obj)"),
            std::string::npos)
      << refusal();
  make_static();
  write(dir / "summary.json", R"({"scene": "drop", "status": "failed", "reason": "no decrease"})");
  EXPECT_NE(refusal().find(dir.string() + ": nothing to show: a static run that failed writes no final.obj "
                                          "(summary.json: no decrease)"),
            std::string::npos)
      << refusal();
  fs::remove_all(dir);
  EXPECT_NE(refusal().find(dir.string() + ": not a simulation's output folder"), std::string::npos) << refusal();
}

TEST_F(Folder, AFrameWithAnotherVertexCountIsRefusedNamingTheFrame) {
  Mesh bigger = rest;
  bigger.vertices.push_back({9, 9, 9});
  write_mesh(dir / "frames" / frame_name(1), bigger);
  const std::string why = refusal();
  EXPECT_NE(why.find((dir / "frames" / frame_name(1)).string() + ": 10 vertices where rest.obj has 9"),
            std::string::npos)
      << why;
}

TEST_F(Folder, AFrameWithOtherFacesIsRefusedNamingTheFrame) {
  Mesh other = rest;
  std::swap(other.faces[0], other.faces[1]);
  write_mesh(dir / "final.obj", other);
  const std::string why = refusal();
  EXPECT_NE(why.find((dir / "final.obj").string() + ": its faces differ"), std::string::npos) << why;
}

TEST_F(Folder, AGapInTheFramesIsRefusedNamingTheMissingFrame) {
  write_mesh(dir / "frames" / frame_name(3), rest);
  fs::remove(dir / "frames" / frame_name(1));
  const std::string why = refusal();
  EXPECT_NE(why.find((dir / "frames" / frame_name(1)).string() + ": missing"), std::string::npos) << why;
}

// An independent decoder of RFC 4648 base64, for the page's data.
std::vector<std::uint8_t> decoded(const std::string& text) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> out;
  unsigned bits = 0, count = 0;
  for (const char c : text) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<unsigned>(digits.find(c));
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<std::uint8_t>(bits >> count));
      bits &= (1u << count) - 1;
    }
  }
  return out;
}

TEST_F(Folder, ThePagesDataDecodesBackToTheFramesAndTheirBending) {
  Mesh bent = lowered(rest, 0.5);
  bent.vertices[4][2] += 0.3;  // the centre raised: the hinges around it bend
  write_mesh(dir / "final.obj", bent);
  const view::Run run = read_run(dir.string());
  std::ostringstream page;
  const PageStats stats = write_page(page, run);
  const std::string html = page.str();
  const std::string open = R"(<script type="application/json" id="hinge-run">)";
  const std::size_t begin = html.find(open) + open.size();
  const nlohmann::json data = nlohmann::json::parse(html.substr(begin, html.find("</script>", begin) - begin));

  const Topology t = build_topology(rest);
  const std::vector<double> theta_bar = hinge_angles(t, rest.vertices);
  ASSERT_EQ(data["positions"].size(), run.frames.size());
  ASSERT_EQ(stats.frames, run.frames.size());
  const Box box{data["box"]["min"].get<Vec3>(), data["box"]["max"].get<Vec3>()};
  const double scale = data["scale"].get<double>();
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const std::vector<std::uint8_t> p = decoded(data["positions"][f].get<std::string>());
    ASSERT_EQ(p.size(), 2 * 3 * rest.vertices.size());
    for (std::size_t i = 0; i < 3 * rest.vertices.size(); ++i) {
      const std::uint16_t q = static_cast<std::uint16_t>(p[2 * i] | (p[2 * i + 1] << 8));
      const std::size_t c = i % 3;
      const double x = box.min[c] + q * ((box.max[c] - box.min[c]) / (position_levels - 1));
      const double half_level = (box.max[c] - box.min[c]) / (2.0 * (position_levels - 1));    // plus rounding:
      ASSERT_NEAR(x, run.frames[f].vertices[i / 3][c], half_level + 4 * u) << f << " " << i;  // |x| <= 1 here
    }
    const std::vector<std::uint8_t> v = decoded(data["values"][f].get<std::string>());
    const std::vector<double> d = bending_deviation(hinge_angles(t, run.frames[f].vertices), theta_bar);
    ASSERT_EQ(v.size(), d.size());
    for (std::size_t h = 0; h < d.size(); ++h) EXPECT_EQ(v[h], std::lround(d[h] / scale * 254)) << f << " " << h;
  }
  double largest = 0;
  for (const double x : bending_deviation(hinge_angles(t, bent.vertices), theta_bar)) largest = std::max(largest, x);
  EXPECT_EQ(scale, largest);  // the bar's top: the largest over all frames (the raised centre's)
  EXPECT_EQ(data["sphere"]["radius"].get<double>(), 0.5);
  EXPECT_EQ(decoded(data["faces"].get<std::string>()).size(), 4 * 3 * rest.faces.size());
}

}  // namespace
}  // namespace hinge::view
