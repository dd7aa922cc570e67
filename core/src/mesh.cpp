// Mesh topology: edges, hinges and the checks of docs/contract.md "Hinges in a mesh"
// (hinge/core/mesh.hpp).
//
// Half-edge h = 3 f + i is edge i of face f = (v0, v1, v2), running v_{i+1} -> v_{i+2}. The half-edges are
// bucketed by their smaller vertex (a counting sort, linear time) and each bucket is sorted by (larger
// vertex, h), so the half-edges of one undirected edge are contiguous, first appearance first. Edges then
// get their indices in order of first appearance by one scan over h, which finds the group of each first
// appearance by binary search in its (short) bucket. No hashing: the result and the error reported (the first
// offending edge in face order) are deterministic, and a vertex of very high degree costs only a sort.
#include "hinge/core/mesh.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "hinge/core/errors.hpp"
#include "hinge/core/predicates.hpp"

namespace hinge {
namespace {

std::string face_name(std::size_t f) {
  return "face " + std::to_string(f) + " (OBJ face " + std::to_string(f + 1) + ")";
}

// "edge 3 -> 7 (OBJ vertices 4 -> 8)" when directed, "edge {3, 7} (OBJ vertices 4, 8)" when not.
std::string edge_name(Index a, Index b, bool directed) {
  const std::string sep = directed ? " -> " : ", ";
  const std::string open = directed ? "" : "{", close = directed ? "" : "}";
  return "edge " + open + std::to_string(a) + sep + std::to_string(b) + close + " (OBJ vertices " +
         std::to_string(a + 1) + sep + std::to_string(b + 1) + ")";
}

// Checks the indices of every face: in range and, when `distinct`, pairwise distinct.
void check_face_indices(const Mesh& mesh, bool distinct) {
  const std::size_t n = mesh.vertices.size();
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& v = mesh.faces[f];
    for (int i = 0; i < 3; ++i) {
      if (v[i] < 0 || static_cast<std::size_t>(v[i]) >= n) {
        throw InputError(face_name(f) + ": vertex index " + std::to_string(v[i]) + " out of range (the mesh has " +
                         std::to_string(n) + " vertices)");
      }
    }
    if (distinct && (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])) {
      throw InputError(face_name(f) + " repeats a vertex: (" + std::to_string(v[0]) + ", " + std::to_string(v[1]) +
                       ", " + std::to_string(v[2]) + ")");
    }
  }
}

}  // namespace

Topology build_topology(const Mesh& mesh) {
  check_face_indices(mesh, true);
  const std::size_t face_count = mesh.faces.size();
  const std::size_t vertex_count = mesh.vertices.size();
  if (face_count > static_cast<std::size_t>(std::numeric_limits<Index>::max() / 3) ||
      vertex_count > static_cast<std::size_t>(std::numeric_limits<Index>::max())) {
    throw InputError("mesh too large: " + std::to_string(face_count) + " faces, " + std::to_string(vertex_count) +
                     " vertices (at most 715827882 faces)");
  }
  const auto& faces = mesh.faces;
  const Index half_count = static_cast<Index>(3 * face_count);
  auto from = [&](Index h) { return faces[h / 3][(h % 3 + 1) % 3]; };
  auto to = [&](Index h) { return faces[h / 3][(h % 3 + 2) % 3]; };
  auto lo = [&](Index h) { return std::min(from(h), to(h)); };
  auto hi = [&](Index h) { return std::max(from(h), to(h)); };

  // Counting sort of the half-edges by their smaller vertex; within a bucket, the keys (larger vertex,
  // h) packed as (hi << 32) | h sort by larger vertex, then by h.
  std::vector<Index> start(vertex_count + 1, 0);
  for (Index h = 0; h < half_count; ++h) ++start[lo(h) + 1];
  for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
  std::vector<std::uint64_t> key(static_cast<std::size_t>(half_count));
  {
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (Index h = 0; h < half_count; ++h) {
      key[fill[lo(h)]++] = std::uint64_t(hi(h)) << 32 | std::uint32_t(h);
    }
  }
  auto key_hi = [&](Index k) { return Index(key[k] >> 32); };
  auto key_h = [&](Index k) { return Index(key[k] & 0xffff'ffffU); };
  for (std::size_t v = 0; v < vertex_count; ++v) {
    if (start[v + 1] - start[v] > 1) std::sort(key.begin() + start[v], key.begin() + start[v + 1]);
  }

  Topology t;
  t.vertex_count = vertex_count;
  t.faces = faces;
  t.face_edges.assign(face_count, {-1, -1, -1});
  t.edges.reserve(static_cast<std::size_t>(half_count) / 2 + 1);

  // Edges in order of first appearance; each validated when it is first met.
  for (Index h = 0; h < half_count; ++h) {
    if (t.face_edges[h / 3][h % 3] >= 0) continue;  // its edge was met at an earlier half-edge
    // h is the first appearance of its edge, whose half-edges are key[k, end) in the bucket of lo(h).
    const Index first = start[lo(h)], last = start[lo(h) + 1];
    const Index k = static_cast<Index>(
        std::lower_bound(key.begin() + first, key.begin() + last, std::uint64_t(hi(h)) << 32) - key.begin());
    Index end = k + 1;
    while (end < last && key_hi(end) == key_hi(k)) ++end;
    const Index size = end - k;
    if (size >= 3) {
      std::string faces_list;
      for (Index j = k; j < end; ++j) {
        faces_list += (j > k ? ", " : "") + face_name(static_cast<std::size_t>(key_h(j) / 3));
      }
      throw InputError(edge_name(lo(h), hi(h), false) + " is shared by " + std::to_string(size) +
                       " faces (non-manifold): " + faces_list);
    }
    Edge e;
    e.a = from(h);
    e.b = to(h);
    e.face[0] = h / 3;
    e.local[0] = static_cast<std::int8_t>(h % 3);
    if (size == 2) {
      const Index g = key_h(k + 1);  // key_h(k) == h, the first appearance
      if (from(g) == e.a) {
        throw InputError(face_name(static_cast<std::size_t>(h / 3)) + " and " +
                         face_name(static_cast<std::size_t>(g / 3)) + " both contain the directed " +
                         edge_name(e.a, e.b, true) + " (inconsistent orientation)");
      }
      e.face[1] = g / 3;
      e.local[1] = static_cast<std::int8_t>(g % 3);
    }
    const Index id = static_cast<Index>(t.edges.size());
    for (Index j = k; j < end; ++j) t.face_edges[key_h(j) / 3][key_h(j) % 3] = id;
    t.edges.push_back(e);
  }

  // Hinges: the interior edges, in edge order. Upper face (x0, x1, x2) = face[0] from the edge's
  // opposite vertex, so that the edge is x1 -> x2; x3 is the lower face's vertex opposite the edge.
  t.hinge_of_edge.assign(t.edges.size(), -1);
  t.hinges.reserve(static_cast<std::size_t>(
      std::count_if(t.edges.begin(), t.edges.end(), [](const Edge& e) { return e.interior(); })));
  for (std::size_t id = 0; id < t.edges.size(); ++id) {
    const Edge& e = t.edges[id];
    if (!e.interior()) continue;
    const auto& upper = faces[e.face[0]];
    const int l = e.local[0];
    Hinge hg;
    hg.x = {upper[l], upper[(l + 1) % 3], upper[(l + 2) % 3], faces[e.face[1]][e.local[1]]};
    hg.upper = e.face[0];
    hg.lower = e.face[1];
    hg.edge = static_cast<Index>(id);
    t.hinge_of_edge[id] = static_cast<Index>(t.hinges.size());
    t.hinges.push_back(hg);
  }
  return t;
}

std::array<double, 12> hinge_coordinates(const Mesh& mesh, const Hinge& h) {
  std::array<double, 12> x;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) x[3 * a + c] = mesh.vertices[h.x[a]][c];
  return x;
}

Mesh hinge_mesh(const std::array<double, 12>& x) {
  Mesh m;
  for (int v = 0; v < 4; ++v) m.vertices.push_back({x[3 * v], x[3 * v + 1], x[3 * v + 2]});
  m.faces = {{0, 1, 2}, {3, 2, 1}};
  return m;
}

void check_faces_nondegenerate(const Mesh& mesh) {
  check_face_indices(mesh, false);  // a repeated index is reported below, as zero area
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& v = mesh.faces[f];
    if (zero_area_exact(mesh.vertices[v[0]], mesh.vertices[v[1]], mesh.vertices[v[2]])) {
      throw InputError(face_name(f) + " (vertices " + std::to_string(v[0]) + ", " + std::to_string(v[1]) + ", " +
                       std::to_string(v[2]) + ") has zero area (collinear or coincident vertices)");
    }
  }
}

}  // namespace hinge
