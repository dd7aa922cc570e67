// Unit tests of read_obj and write_obj (io/src/obj.cpp): bit-exact coordinates, the accepted
// syntax, and errors that name the file and line.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "hinge/core/errors.hpp"
#include "hinge/io/obj.hpp"

namespace hinge {
namespace {

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

Mesh read_text(const std::string& text, const std::string& name = "test.obj") {
  std::istringstream in(text);
  return io::read_obj(in, name);
}

// The message of the InputError that reading `text` throws; fails the test when it throws nothing.
std::string read_error(const std::string& text, const std::string& name = "test.obj") {
  try {
    read_text(text, name);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no hinge::InputError for:\n" << text;
  return {};
}

// Random finite doubles of every exponent: uniform random bit patterns (about half are huge or tiny),
// with a share of subnormals, zeros of both signs, and the extremes.
std::vector<double> random_doubles(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<double> out = {0.0,
                             -0.0,
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::max(),
                             -std::numeric_limits<double>::max(),
                             0.1,
                             1.0 / 3.0};
  while (out.size() < count) {
    std::uint64_t bits = rng();
    if (out.size() % 8 == 0) bits &= 0x800f'ffff'ffff'ffffULL;  // subnormal (or zero)
    if (out.size() % 8 == 1) {                                  // moderate exponents, around 1
      bits = (bits & 0x800f'ffff'ffff'ffffULL) | (std::uint64_t(1023 - 30 + rng() % 60) << 52);
    }
    const double x = std::bit_cast<double>(bits);
    if (std::isfinite(x)) out.push_back(x);
  }
  return out;
}

void expect_same_bits(const std::vector<double>& expected, const Mesh& mesh) {
  ASSERT_EQ(mesh.vertices.size() * 3, expected.size());
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const double got = mesh.vertices[i / 3][i % 3];
    if (std::bit_cast<std::uint64_t>(got) != std::bit_cast<std::uint64_t>(expected[i]) && mismatches++ < 5) {
      ADD_FAILURE() << "coordinate " << i << ": wrote " << expected[i] << ", read " << got;
    }
  }
  EXPECT_EQ(mismatches, 0u);
}

TEST(ObjRoundTrip, ShortestRoundTripCoordinatesReadBackBitForBit) {
  const std::vector<double> values = random_doubles(3 * 3000, 1);
  Mesh m;
  for (std::size_t i = 0; i < values.size(); i += 3) {
    m.vertices.push_back({values[i], values[i + 1], values[i + 2]});
  }
  for (Index v = 0; v + 2 < Index(m.vertices.size()); v += 3) m.faces.push_back({v, v + 1, v + 2});
  std::ostringstream out;
  io::write_obj(out, m);
  const Mesh back = read_text(out.str());
  expect_same_bits(values, back);
  EXPECT_EQ(back.faces, m.faces);
}

TEST(ObjRoundTrip, SeventeenDigitCoordinatesReadBackBitForBit) {
  // Written with %.17g by another program (17 significant digits always identify a double).
  const std::vector<double> values = random_doubles(3 * 3000, 2);
  std::string text;
  char line[128];
  for (std::size_t i = 0; i < values.size(); i += 3) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", values[i], values[i + 1], values[i + 2]);
    text += line;
  }
  expect_same_bits(values, read_text(text + "f 1 2 3\n"));
}

TEST(ObjWrite, WritesShortestCoordinatesAndOneBasedFaces) {
  Mesh m;
  m.vertices = {{0.5, 1.0, -0.0}, {0.1, 1e300, 5e-324}, {-2.5, 3.0, 1e-7}};
  m.faces = {{0, 1, 2}, {2, 1, 0}};
  std::ostringstream out;
  io::write_obj(out, m);
  // Integral values get ".0" (io/number.hpp: every number looks like a double).
  EXPECT_EQ(out.str(), "v 0.5 1.0 -0.0\nv 0.1 1e+300 5e-324\nv -2.5 3.0 1e-07\nf 1 2 3\nf 3 2 1\n");
}

TEST(ObjWrite, WritesTheCommentFirst) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.faces = {{0, 1, 2}};
  std::ostringstream out;
  io::write_obj(out, m, "a mesh");
  EXPECT_EQ(out.str(), "# a mesh\nv 0.0 0.0 0.0\nv 1.0 0.0 0.0\nv 0.0 1.0 0.0\nf 1 2 3\n");
}

TEST(ObjRead, AcceptsFaceIndexFormsAndNegativeRelativeIndices) {
  const Mesh m = read_text(
      "v 0 0 0\n"
      "v 1 0 0\n"
      "v 0 1 0\n"
      "vt 0 0\nvt 1 0\nvn 0 0 1\n"
      "f 1/1 2/2 3/1\n"
      "f 1//1 2//1 3//1\n"
      "f 1/2/1 2/1/1 3/2/1\n"
      "f -3 -2 -1\n"
      "v 1 1 0\n"
      "f -3/1 -1/-1/-1 -2//1\n");
  ASSERT_EQ(m.vertices.size(), 4u);
  ASSERT_EQ(m.faces.size(), 5u);
  for (int f = 0; f < 4; ++f) EXPECT_EQ(m.faces[f], (std::array<Index, 3>{0, 1, 2})) << "face " << f;
  EXPECT_EQ(m.faces[4], (std::array<Index, 3>{1, 3, 2}));
}

TEST(ObjRead, AcceptsPlusSignsCrlfCommentsWhitespaceAndOtherLines) {
  const Mesh m = read_text(
      "# a comment\r\n"
      "mtllib x.mtl\r\n"
      "o object\r\n"
      "\r\n"
      "   \t \r\n"
      "  v\t+1.5  -2e-3 +.25   \r\n"
      "v 1 2 3 1.0\r\n"  // optional w
      "v 4 5 6 0.5 0.5 0.5 # vertex colours\r\n"
      "g group\r\ns off\r\nusemtl m\r\nl 1 2\r\np 1\r\n"
      "f +1 2 3 # trailing comment\r\n");
  ASSERT_EQ(m.vertices.size(), 3u);
  EXPECT_EQ(m.vertices[0], (std::array<double, 3>{1.5, -2e-3, 0.25}));
  EXPECT_EQ(m.vertices[1], (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(m.vertices[2], (std::array<double, 3>{4, 5, 6}));
  ASSERT_EQ(m.faces.size(), 1u);
  EXPECT_EQ(m.faces[0], (std::array<Index, 3>{0, 1, 2}));
}

TEST(ObjRead, KeepsNegativeZeroAndSubnormals) {
  const Mesh m =
      read_text("v -0 -0.0 4.9406564584124654e-324\nv 2.2250738585072014e-308 1e-310 -1e-320\nv 1 1 1\nf 1 2 3\n");
  EXPECT_TRUE(std::signbit(m.vertices[0][0]));
  EXPECT_TRUE(std::signbit(m.vertices[0][1]));
  EXPECT_EQ(m.vertices[0][2], std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(m.vertices[1][0], std::numeric_limits<double>::min());
  EXPECT_EQ(m.vertices[1][1], 1e-310);
  EXPECT_EQ(m.vertices[1][2], -1e-320);
}

TEST(ObjRead, AllowsForwardReferencesWithPositiveIndices) {
  const Mesh m = read_text("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  ASSERT_EQ(m.faces.size(), 1u);
  EXPECT_EQ(m.faces[0], (std::array<Index, 3>{0, 1, 2}));
}

TEST(ObjRead, RejectsNonFiniteCoordinatesNamingFileAndLine) {
  for (const std::string bad : {"inf", "-inf", "+inf", "infinity", "nan", "-nan", "NaN", "1e400", "-1e309"}) {
    const std::string msg = read_error("v 0 0 0\n# comment\nv 1 " + bad + " 0\n", "mesh.obj");
    EXPECT_TRUE(contains(msg, "mesh.obj:3: ")) << bad;
    EXPECT_TRUE(contains(msg, bad)) << bad;
  }
  // Underflow to zero is refused too: the text does not name a double.
  EXPECT_TRUE(contains(read_error("v 1e-400 0 0\n", "mesh.obj"), "mesh.obj:1: "));
}

TEST(ObjRead, RejectsMalformedCoordinatesNamingFileAndLine) {
  for (const std::string bad : {"1.0x", "+-1", "++1", "--1", "+", "-", "1e", "0x1p3", "1,5", "one"}) {
    const std::string msg = read_error("v 0 0 0\r\nv 1 " + bad + " 0\r\n");
    EXPECT_TRUE(contains(msg, "test.obj:2: ")) << bad;
    EXPECT_TRUE(contains(msg, "'" + bad + "'")) << bad;
  }
  EXPECT_TRUE(contains(read_error("v 1 2\n"), "test.obj:1: "));
  EXPECT_TRUE(contains(read_error("v 1 2 3 w\n"), "test.obj:1: "));
}

TEST(ObjRead, RejectsNonTriangleFacesNamingFileAndLine) {
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  std::string msg = read_error(verts + "f 1 2 3 4\n");
  EXPECT_TRUE(contains(msg, "test.obj:5: "));
  EXPECT_TRUE(contains(msg, "4 vertices"));
  EXPECT_TRUE(contains(read_error(verts + "\nf 1 2\n"), "test.obj:6: "));
  EXPECT_TRUE(contains(read_error(verts + "f\n"), "test.obj:5: "));
}

TEST(ObjRead, RejectsBadFaceIndicesNamingFileAndLine) {
  const std::string verts = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
  EXPECT_TRUE(contains(read_error(verts + "f 1 2 4\n# end\n"), "test.obj:4: "));  // checked at the end
  std::string msg = read_error(verts + "f 1 2 3\nf 1 2 5\n\n");
  EXPECT_TRUE(contains(msg, "test.obj:5: "));
  EXPECT_TRUE(contains(msg, "5"));
  EXPECT_TRUE(contains(read_error(verts + "f 0 1 2\n"), "test.obj:4: "));
  EXPECT_TRUE(contains(read_error(verts + "f -4 -1 -2\n"), "test.obj:4: "));
  EXPECT_TRUE(contains(read_error(verts + "f 1 2 99999999999\n"), "test.obj:4: "));
  for (const std::string bad : {"1/", "1/2/3/4", "a", "1.0", "1//", "/1", "1/x", "1/2/", "//"}) {
    msg = read_error(verts + "f 1 2 " + bad + "\n");
    EXPECT_TRUE(contains(msg, "test.obj:4: ")) << bad;
    EXPECT_TRUE(contains(msg, "'" + bad + "'")) << bad;
  }
}

TEST(ObjRead, RejectsAMeshWithNoFacesNamingTheFile) {
  // docs/contract.md (version 2): an empty file, or one with vertices and no faces, is not a mesh.
  for (const std::string text : {"", "\n# only a comment\n", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "vt 0 0\nvn 0 0 1\n"}) {
    const std::string msg = read_error(text, "empty.obj");
    EXPECT_TRUE(contains(msg, "empty.obj: ")) << text;
    EXPECT_TRUE(contains(msg, "no faces")) << text;
  }
}

TEST(ObjRead, ReadsFileByPathAndNamesMissingFile) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string path = (dir / ("hinge_obj_test_" + std::to_string(std::random_device{}()) + ".obj")).string();
  {
    std::ofstream out(path, std::ios::binary);
    out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3 1\n";
  }
  try {
    io::read_obj(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), path + ":5: "));
  }
  std::filesystem::remove(path);
  try {
    io::read_obj(path);
    ADD_FAILURE() << "no error for a missing file";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), path));
  }
}

}  // namespace
}  // namespace hinge
