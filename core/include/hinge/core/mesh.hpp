// hinge/core/mesh.hpp: an indexed triangle mesh and its hinges (docs/contract.md, "Hinges in a mesh").
//
// A hinge is an interior edge with its two faces. For the edge x1 -> x2 as it appears in the cyclic
// order of the upper face (x0, x1, x2), the lower face contains x2 -> x1 and its third vertex is x3:
//
//              x0
//             /  \          upper face  (x0, x1, x2), counter-clockwise about n
//           x1 -- x2        hinge edge  e0 = x2 - x1
//             \  /          lower face  (x3, x2, x1), counter-clockwise about n~
//              x3
//
// Variables of a hinge: x0, x1, x2, x3 (12); global index of coordinate c of vertex v: 3 v + c.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hinge {

using Index = std::int32_t;

// Vertex positions are the exact doubles read from the input; faces are 0-based vertex indices.
struct Mesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<Index, 3>> faces;
};

// An undirected edge with its one or two faces. a -> b is its direction in face[0]; face[1] (if any)
// contains b -> a. local[k] is the edge's index in face[k]: the local index (0, 1, 2) of the vertex
// opposite it, so that edge i of face (v0, v1, v2) runs v_{i+1} -> v_{i+2}.
struct Edge {
  Index a = -1, b = -1;
  std::array<Index, 2> face{-1, -1};
  std::array<std::int8_t, 2> local{-1, -1};
  bool interior() const { return face[1] >= 0; }
};

// A hinge: an interior edge. x = (x0, x1, x2, x3) as in the diagram above, upper = face[0] of the edge.
struct Hinge {
  std::array<Index, 4> x{};
  Index upper = -1, lower = -1;  // face indices
  Index edge = -1;               // index into Topology::edges
};

struct Topology {
  std::size_t vertex_count = 0;
  std::vector<std::array<Index, 3>> faces;
  std::vector<Edge> edges;                       // every edge once, in order of first appearance
  std::vector<std::array<Index, 3>> face_edges;  // face_edges[f][i]: the edge opposite vertex i of f
  std::vector<Hinge> hinges;                     // the interior edges, in the order of `edges`
  std::vector<Index> hinge_of_edge;              // edge -> hinge index, -1 for a boundary edge
};

// Builds the topology of `mesh`. Throws hinge::InputError naming the face or edge for: a vertex index
// out of range, a face that repeats a vertex, an edge in three or more faces (non-manifold), two faces
// that use the same directed edge (inconsistent orientation).
Topology build_topology(const Mesh& mesh);

// The 12 coordinates of hinge h, in the order x0, x1, x2, x3.
std::array<double, 12> hinge_coordinates(const Mesh& mesh, const Hinge& h);

// The hinge x (x0, x1, x2, x3) as a mesh of its two triangles, (x0, x1, x2) and (x3, x2, x1): vertex v is x_v,
// so that the mesh's global variables are the hinge's own (a one-hinge mesh for the mesh evaluators).
Mesh hinge_mesh(const std::array<double, 12>& x);

// Throws hinge::InputError naming the first face whose three vertices have exactly zero area (collinear
// or coincident), judged exactly on the doubles of `mesh` (docs/contract.md).
void check_faces_nondegenerate(const Mesh& mesh);

}  // namespace hinge
