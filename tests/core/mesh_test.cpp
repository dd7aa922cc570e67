// Unit tests of build_topology and check_faces_nondegenerate (core/src/mesh.cpp) against
// docs/contract.md "Hinges in a mesh" and "The hinge stencil".
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <random>
#include <string>

#include "hinge/core/errors.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/core/predicates.hpp"

namespace hinge {
namespace {

// Whether `text` contains `part`, with both shown on failure.
::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

// The message of the InputError that `f` throws; fails the test when it throws nothing.
template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no hinge::InputError thrown";
  return {};
}

// A grid of nx by ny unit squares in the plane z = 0, each split into two counter-clockwise triangles.
Mesh grid(int nx, int ny) {
  Mesh m;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) m.vertices.push_back({double(i), double(j), 0.0});
  }
  auto id = [&](int i, int j) { return Index(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return m;
}

// The regular octahedron, outward (counter-clockwise seen from outside) faces.
Mesh octahedron() {
  Mesh m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// True when the cyclic order of face f contains the directed edge a -> b.
bool has_directed_edge(const std::array<Index, 3>& f, Index a, Index b) {
  for (int i = 0; i < 3; ++i) {
    if (f[i] == a && f[(i + 1) % 3] == b) return true;
  }
  return false;
}

// Every structural invariant of a Topology that the header promises.
void expect_consistent(const Mesh& m, const Topology& t) {
  ASSERT_EQ(t.vertex_count, m.vertices.size());
  ASSERT_EQ(t.faces, m.faces);
  ASSERT_EQ(t.face_edges.size(), m.faces.size());
  ASSERT_EQ(t.hinge_of_edge.size(), t.edges.size());
  // face_edges[f][i] is the edge opposite vertex i, and that edge lists f with local index i.
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    for (int i = 0; i < 3; ++i) {
      const Index id = t.face_edges[f][i];
      ASSERT_GE(id, 0);
      const Edge& e = t.edges[id];
      const Index u = m.faces[f][(i + 1) % 3], w = m.faces[f][(i + 2) % 3];
      EXPECT_EQ(std::minmax(e.a, e.b), std::minmax(u, w));
      const bool first = e.face[0] == Index(f) && e.local[0] == i;
      const bool second = e.face[1] == Index(f) && e.local[1] == i;
      EXPECT_TRUE(first || second) << "face " << f << " local " << i;
    }
  }
  // Edges in order of first appearance: their first half-edges 3 f + i increase strictly.
  for (std::size_t id = 0; id + 1 < t.edges.size(); ++id) {
    EXPECT_LT(3 * t.edges[id].face[0] + t.edges[id].local[0], 3 * t.edges[id + 1].face[0] + t.edges[id + 1].local[0]);
  }
  // a -> b runs in face[0], b -> a in face[1]; hinges are the interior edges, in edge order.
  std::size_t interior = 0;
  for (std::size_t id = 0; id < t.edges.size(); ++id) {
    const Edge& e = t.edges[id];
    EXPECT_TRUE(has_directed_edge(m.faces[e.face[0]], e.a, e.b));
    if (!e.interior()) {
      EXPECT_EQ(t.hinge_of_edge[id], -1);
      continue;
    }
    EXPECT_LT(e.face[0], e.face[1]);
    EXPECT_TRUE(has_directed_edge(m.faces[e.face[1]], e.b, e.a));
    ASSERT_EQ(t.hinge_of_edge[id], Index(interior));
    const Hinge& h = t.hinges[interior++];
    EXPECT_EQ(h.edge, Index(id));
    EXPECT_EQ(h.upper, e.face[0]);
    EXPECT_EQ(h.lower, e.face[1]);
    EXPECT_EQ(h.x[1], e.a);
    EXPECT_EQ(h.x[2], e.b);
    // Upper face is (x0, x1, x2) up to rotation, lower face (x3, x2, x1).
    EXPECT_TRUE(has_directed_edge(m.faces[h.upper], h.x[0], h.x[1]));
    EXPECT_TRUE(has_directed_edge(m.faces[h.upper], h.x[2], h.x[0]));
    EXPECT_TRUE(has_directed_edge(m.faces[h.lower], h.x[3], h.x[2]));
    EXPECT_TRUE(has_directed_edge(m.faces[h.lower], h.x[1], h.x[3]));
  }
  EXPECT_EQ(t.hinges.size(), interior);
}

TEST(Topology, TwoTriangleHingeLabelsMatchConventions) {
  // The docs/contract.md check hinge: x1 = (0,0,0), x2 = (1,0,0), x0 = (0.5,1,0), x3 = (0.5,-1,0), stored as
  // vertices 0 = x1, 1 = x2, 2 = x0, 3 = x3; upper face (x0, x1, x2), lower face (x3, x2, x1).
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
  m.faces = {{2, 0, 1}, {3, 1, 0}};
  const Topology t = build_topology(m);
  expect_consistent(m, t);
  // Edges by first appearance: face 0 gives 0->1, 1->2, 2->0; face 1 adds 0->3, 3->1.
  ASSERT_EQ(t.edges.size(), 5u);
  EXPECT_EQ(t.edges[0].a, 0);
  EXPECT_EQ(t.edges[0].b, 1);
  EXPECT_EQ(t.edges[0].face, (std::array<Index, 2>{0, 1}));
  EXPECT_EQ(t.edges[0].local, (std::array<std::int8_t, 2>{0, 0}));
  EXPECT_EQ(t.edges[3].a, 0);
  EXPECT_EQ(t.edges[3].b, 3);
  EXPECT_EQ(t.face_edges[0], (std::array<Index, 3>{0, 1, 2}));
  EXPECT_EQ(t.face_edges[1], (std::array<Index, 3>{0, 3, 4}));
  EXPECT_EQ(t.hinge_of_edge, (std::vector<Index>{0, -1, -1, -1, -1}));
  ASSERT_EQ(t.hinges.size(), 1u);
  const Hinge& h = t.hinges[0];
  EXPECT_EQ(h.x, (std::array<Index, 4>{2, 0, 1, 3}));
  EXPECT_EQ(h.upper, 0);
  EXPECT_EQ(h.lower, 1);
  EXPECT_EQ(h.edge, 0);

  // Geometry of the labels: n = (x1 - x0) x (x2 - x0) points along +z, flat hinge has orientation 0, and
  // lifting x0 along +n gives theta < 0, the sign hinge_orientation_exact reports.
  const auto& x = m.vertices;
  const Point x0 = x[h.x[0]], x1 = x[h.x[1]], x2 = x[h.x[2]], x3 = x[h.x[3]];
  const double nz = (x1[0] - x0[0]) * (x2[1] - x0[1]) - (x1[1] - x0[1]) * (x2[0] - x0[0]);
  EXPECT_GT(nz, 0.0);
  EXPECT_EQ(hinge_orientation_exact(x0, x1, x2, x3), 0);
  EXPECT_EQ(hinge_orientation_exact({x0[0], x0[1], 0.25}, x1, x2, x3), -1);
}

TEST(Topology, UpperFaceIsTheFaceWhereTheEdgeFirstAppears) {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}};
  m.faces = {{3, 1, 0}, {2, 0, 1}};  // the previous test's faces, swapped
  const Topology t = build_topology(m);
  expect_consistent(m, t);
  ASSERT_EQ(t.hinges.size(), 1u);
  EXPECT_EQ(t.hinges[0].x, (std::array<Index, 4>{3, 1, 0, 2}));
  EXPECT_EQ(t.hinges[0].upper, 0);
  EXPECT_EQ(t.hinges[0].lower, 1);
}

TEST(Topology, ClosedOctahedronHasEveryEdgeInterior) {
  const Mesh m = octahedron();
  const Topology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(t.edges.size(), 3 * m.faces.size() / 2);  // E = 3F/2 on a closed mesh
  EXPECT_EQ(t.hinges.size(), t.edges.size());
  EXPECT_EQ(m.vertices.size() - t.edges.size() + m.faces.size(), 2u);  // Euler characteristic of a sphere
  EXPECT_EQ(std::count(t.hinge_of_edge.begin(), t.hinge_of_edge.end(), -1), 0);
  // Convex with outward normals: every hinge is a ridge, theta > 0, orientation +1.
  for (const Hinge& h : t.hinges) {
    EXPECT_EQ(hinge_orientation_exact(m.vertices[h.x[0]], m.vertices[h.x[1]], m.vertices[h.x[2]], m.vertices[h.x[3]]),
              1);
  }
}

TEST(Topology, OpenGridCountsBoundaryEdges) {
  const int nx = 7, ny = 4;
  const Mesh m = grid(nx, ny);
  const Topology t = build_topology(m);
  expect_consistent(m, t);
  const std::size_t edges = std::size_t(nx * (ny + 1) + ny * (nx + 1) + nx * ny);
  const std::size_t boundary = std::size_t(2 * (nx + ny));
  EXPECT_EQ(t.edges.size(), edges);
  EXPECT_EQ(t.hinges.size(), edges - boundary);
  EXPECT_EQ(std::size_t(std::count(t.hinge_of_edge.begin(), t.hinge_of_edge.end(), -1)), boundary);
  EXPECT_EQ(m.vertices.size() - t.edges.size() + m.faces.size(), 1u);  // a disk
  for (const Hinge& h : t.hinges) {                                    // a flat grid: every hinge has orientation 0
    EXPECT_EQ(hinge_orientation_exact(m.vertices[h.x[0]], m.vertices[h.x[1]], m.vertices[h.x[2]], m.vertices[h.x[3]]),
              0);
  }
}

TEST(Topology, ShuffledFacesAndRotatedCornersGiveConsistentTopology) {
  Mesh m = grid(9, 6);
  std::mt19937 rng(7);
  std::shuffle(m.faces.begin(), m.faces.end(), rng);
  for (auto& f : m.faces) std::rotate(f.begin(), f.begin() + rng() % 3, f.end());
  const Topology t = build_topology(m);
  expect_consistent(m, t);
  EXPECT_EQ(t.hinges.size(), std::size_t(9 * 7 + 6 * 10 + 9 * 6 - 2 * (9 + 6)));
}

TEST(Topology, EmptyMeshHasNoEdges) {
  const Topology t = build_topology(Mesh{});
  EXPECT_TRUE(t.edges.empty());
  EXPECT_TRUE(t.hinges.empty());
}

TEST(Topology, RejectsNonManifoldEdgeNamingAllFaces) {
  // Faces 3, 5 and 8 share the undirected edge {4, 9}; the others are unrelated triangles.
  Mesh m;
  for (int i = 0; i < 20; ++i) m.vertices.push_back({double(i), double(i * i % 7), 0.0});
  m.faces = {{0, 1, 2}, {10, 11, 12}, {13, 14, 15}, {4, 9, 5}, {16, 17, 18},
             {9, 4, 6}, {1, 0, 3},    {0, 2, 19},   {9, 4, 7}};
  const std::string msg = input_error_of([&] { build_topology(m); });
  EXPECT_TRUE(contains(msg, "face 3 (OBJ face 4)"));
  EXPECT_TRUE(contains(msg, "face 5 (OBJ face 6)"));
  EXPECT_TRUE(contains(msg, "face 8 (OBJ face 9)"));
  EXPECT_TRUE(contains(msg, "{4, 9}"));
  EXPECT_TRUE(contains(msg, "non-manifold"));
}

TEST(Topology, RejectsInconsistentOrientationNamingBothFaces) {
  // Faces 2 and 6 both run 5 -> 8.
  Mesh m;
  for (int i = 0; i < 12; ++i) m.vertices.push_back({double(i), double(i % 3), 0.0});
  m.faces = {{0, 1, 2}, {2, 1, 3}, {5, 8, 4}, {9, 10, 11}, {3, 1, 9}, {0, 2, 10}, {8, 6, 5}};
  const std::string msg = input_error_of([&] { build_topology(m); });
  EXPECT_TRUE(contains(msg, "face 2 (OBJ face 3)"));
  EXPECT_TRUE(contains(msg, "face 6 (OBJ face 7)"));
  EXPECT_TRUE(contains(msg, "5 -> 8"));
  EXPECT_TRUE(contains(msg, "inconsistent orientation"));
}

TEST(Topology, RejectsRepeatedVertex) {
  Mesh m = grid(2, 2);
  m.faces.push_back({4, 7, 4});
  const std::string msg = input_error_of([&] { build_topology(m); });
  EXPECT_TRUE(contains(msg, "face 8 (OBJ face 9)"));
  EXPECT_TRUE(contains(msg, "repeats a vertex"));
}

TEST(Topology, RejectsVertexIndexOutOfRange) {
  Mesh m = grid(2, 2);  // 9 vertices
  m.faces[5][1] = 9;
  std::string msg = input_error_of([&] { build_topology(m); });
  EXPECT_TRUE(contains(msg, "face 5 (OBJ face 6)"));
  EXPECT_TRUE(contains(msg, "out of range"));
  m.faces[5][1] = -1;
  msg = input_error_of([&] { build_topology(m); });
  EXPECT_TRUE(contains(msg, "face 5 (OBJ face 6)"));
  EXPECT_TRUE(contains(msg, "-1"));
}

TEST(Topology, CheckFacesNondegenerateNamesTheZeroAreaFace) {
  Mesh m = grid(3, 3);
  EXPECT_NO_THROW(check_faces_nondegenerate(m));
  // Vertex 6 = (2, 1, 0) moves onto the segment from vertex 5 = (1, 1, 0) to vertex 10 = (2, 2, 0): the
  // faces before face 8 = (5, 6, 10) keep nonzero area, face 8 loses it.
  m.vertices[6] = {1.5, 1.5, 0.0};
  const std::string msg = input_error_of([&] { check_faces_nondegenerate(m); });
  EXPECT_TRUE(contains(msg, "face 8 (OBJ face 9)"));
  EXPECT_TRUE(contains(msg, "zero area (collinear or coincident vertices)"));
  // Coincident vertices and a repeated index are zero area too.
  Mesh c;
  c.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}};
  c.faces = {{0, 1, 2}};
  EXPECT_TRUE(contains(input_error_of([&] { check_faces_nondegenerate(c); }), "face 0 (OBJ face 1)"));
  c.vertices[2] = {0, 1, 0};
  EXPECT_NO_THROW(check_faces_nondegenerate(c));
  c.faces = {{0, 1, 1}};
  EXPECT_TRUE(contains(input_error_of([&] { check_faces_nondegenerate(c); }), "zero area"));
}

TEST(Topology, LargeGridCountsEdgesAndHinges) {
  // Speed is a benchmark's business, not a test's: this checks the counts on a 300 x 301 grid.
  const Mesh m = grid(299, 300);  // 90,300 vertices
  const Topology t = build_topology(m);
  EXPECT_EQ(t.edges.size(), std::size_t(299 * 301 + 300 * 300 + 299 * 300));
  EXPECT_EQ(t.hinges.size(), t.edges.size() - 2 * (299 + 300));
}

TEST(Topology, HighDegreeVertexFanHasOneHingePerSpoke) {
  // A closed fan: vertex 0 surrounded by a ring of 200,000 vertices (a bucket of 400,000 half-edges).
  const int ring = 200000;
  Mesh m;
  m.vertices.push_back({0, 0, 0});
  for (int i = 0; i < ring; ++i) m.vertices.push_back({double(i), 1.0, 0.0});
  for (int i = 0; i < ring; ++i) m.faces.push_back({0, Index(1 + i), Index(1 + (i + 1) % ring)});
  const Topology t = build_topology(m);
  EXPECT_EQ(t.edges.size(), std::size_t(2 * ring));
  EXPECT_EQ(t.hinges.size(), std::size_t(ring));
}

}  // namespace
}  // namespace hinge
