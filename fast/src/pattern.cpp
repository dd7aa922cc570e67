// The block sparsity of the bending Hessian and the slot of every block Algorithm 2 writes
// (hinge/fast/pattern.hpp). Built once per topology in linear time plus a sort of each (short) column.
#include "hinge/fast/pattern.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "hinge/core/errors.hpp"

namespace hinge::fast {

Pattern::Pattern(const Topology& topology, EdgeOrientation orientation)
    : vertex_count_(topology.vertex_count), orientation_(orientation) {
  const auto& faces = topology.faces;
  const std::size_t n = vertex_count_;

  // Faces in some hinge; only they write (a face with three boundary edges has c_i = 0 throughout).
  std::vector<char> active(faces.size(), 0);
  for (const Hinge& h : topology.hinges) active[h.upper] = active[h.lower] = 1;

  // Block pairs (a, b), a < b, bucketed by column vertex b: the edges of active faces and each hinge's
  // (x0, x3); the diagonal of every vertex of an active face.
  std::vector<char> diagonal(n, 0);
  std::vector<std::int64_t> start(n + 1, 0);
  auto for_each_pair = [&](auto&& f) {
    for (const Edge& e : topology.edges)
      if (active[e.face[0]] || (e.face[1] >= 0 && active[e.face[1]])) f(std::min(e.a, e.b), std::max(e.a, e.b));
    for (const Hinge& h : topology.hinges)
      if (h.x[0] != h.x[3]) f(std::min(h.x[0], h.x[3]), std::max(h.x[0], h.x[3]));
  };
  for_each_pair([&](Index, Index b) { ++start[b + 1]; });
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (active[f])
      for (Index v : faces[f]) diagonal[v] = 1;
  for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v] + diagonal[v];
  block_rows_.assign(static_cast<std::size_t>(start[n]), -1);
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for_each_pair([&](Index a, Index b) { block_rows_[fill[b]++] = a; });
    for (std::size_t v = 0; v < n; ++v)
      if (diagonal[v]) block_rows_[fill[v]++] = static_cast<Index>(v);
  }
  // Sort and deduplicate each column, then compact.
  block_start_.assign(n + 1, 0);
  std::int64_t out = 0;
  for (std::size_t v = 0; v < n; ++v) {
    const auto first = block_rows_.begin() + start[v], last = block_rows_.begin() + start[v + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    block_start_[v] = out;
    for (auto it = first; it != end; ++it) block_rows_[out++] = *it;
  }
  block_start_[n] = out;
  block_rows_.resize(static_cast<std::size_t>(out));
  block_rows_.shrink_to_fit();

  // Scalar columns: vertex b with K_b off-diagonal blocks has columns of 3 K_b + 1, + 2, + 3 entries.
  outer_.assign(3 * n + 1, 0);
  diagonal_base_.assign(n, -1);
  stride_.assign(n, 0);
  std::int64_t total = 0;
  for (std::size_t b = 0; b < n; ++b) {
    const std::int64_t blocks = block_start_[b + 1] - block_start_[b];
    const std::int64_t K = diagonal[b] ? blocks - 1 : blocks;  // (a vertex without diagonal has no blocks)
    for (int c = 0; c < 3; ++c) {
      outer_[3 * b + c] = static_cast<SlotIndex>(total);
      total += blocks ? 3 * K + c + 1 : 0;
      if (total > std::numeric_limits<SlotIndex>::max())
        throw InputError("mesh too large for one sparse matrix: the Hessian would have more than 2^31 - 1 entries");
    }
    stride_[b] = static_cast<SlotIndex>(3 * K + 1);
    if (blocks) diagonal_base_[b] = static_cast<SlotIndex>(outer_[3 * b] + 3 * K);
  }
  outer_[3 * n] = static_cast<SlotIndex>(total);

  // Faces and hinges.
  faces_.assign(faces.size(), Face{});
  for (std::size_t f = 0; f < faces.size(); ++f) {
    Face& face = faces_[f];
    face.v = faces[f];
    if (!active[f]) continue;
    face.lowest = std::min({face.v[0], face.v[1], face.v[2]});
    face.highest = std::max({face.v[0], face.v[1], face.v[2]});
    for (int i = 0; i < 3; ++i) {
      const Index e = topology.face_edges[f][i];
      face.hinge[i] = topology.hinge_of_edge[e];
      face.edge_slot[i] = find_block(face.v[(i + 1) % 3], face.v[(i + 2) % 3]);
    }
  }
  hinges_.assign(topology.hinges.size(), OwnedHinge{});
  for (std::size_t h = 0; h < topology.hinges.size(); ++h) {
    const Edge& e = topology.edges[topology.hinges[h].edge];
    const int which = orientation == EdgeOrientation::first_face ? 0 : 1;
    OwnedHinge& o = hinges_[h];
    const Index owner = e.face[which];
    const int local = e.local[which];
    o.other_face = e.face[1 - which];
    o.s = faces[o.other_face][e.local[1 - which]];
    const auto& v = faces[owner];
    const Index p = v[local], q = v[(local + 1) % 3], r = v[(local + 2) % 3];
    o.slot_ps = p == o.s ? -1 : find_block(p, o.s);
    o.slot_qs = find_block(q, o.s);
    o.slot_rs = find_block(r, o.s);
    Face& face = faces_[owner];
    face.owns |= 1u << local;
    face.lowest = std::min(face.lowest, o.s);
    face.highest = std::max(face.highest, o.s);
  }

  // First writes: the assembly visits faces in increasing order and, within a face, writes the blocks
  // of its owned edges (k increasing: (s, s), (p, s), (q, s), (r, s)) and then, for i = 0, 1, 2, the
  // diagonal block of vertex i and the block off[i]. Whatever the threads, each block receives its
  // writes in this order (assemble.hpp), so the first one can store.
  std::vector<bool> touched(static_cast<std::size_t>(total), false);
  auto first_time = [&touched](SlotIndex base) {
    const bool first = !touched[static_cast<std::size_t>(base)];
    touched[static_cast<std::size_t>(base)] = true;
    return first;
  };
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    Face& face = faces_[f];
    if (face.highest < 0) continue;
    std::uint32_t first = 0;
    for (int k = 0; k < 3; ++k) {
      if (!((face.owns >> k) & 1u)) continue;
      const OwnedHinge& o = hinges_[face.hinge[k]];
      if (first_time(diagonal_base_[o.s])) first |= 1u << hinge_bit(k, 0);
      const SlotIndex slots[3] = {o.slot_ps, o.slot_qs, o.slot_rs};
      for (int a = 0; a < 3; ++a) {
        const SlotIndex base = slots[a] >= 0 ? slots[a] : diagonal_base_[o.s];  // -1: p == s, a diagonal block
        if (first_time(base)) first |= 1u << hinge_bit(k, 1 + a);
      }
    }
    for (int i = 0; i < 3; ++i) {
      if (first_time(diagonal_base_[face.v[i]])) first |= 1u << diagonal_bit(i);
      if (first_time(face.edge_slot[(i + 2) % 3])) first |= 1u << edge_bit(i);
    }
    face.first = first;
  }

  // The order in which the assembly first touches each vertex's columns (for its prefetches).
  first_writer_.assign(n, std::numeric_limits<Index>::max());
  for (std::size_t f = faces_.size(); f-- > 0;) {
    const Face& face = faces_[f];
    if (face.highest < 0) continue;
    for (Index v : face.v) first_writer_[v] = static_cast<Index>(f);
    for (int k = 0; k < 3; ++k)
      if ((face.owns >> k) & 1u) first_writer_[hinges_[face.hinge[k]].s] = static_cast<Index>(f);
  }
  first_write_order_.clear();
  for (std::size_t v = 0; v < n; ++v)
    if (first_writer_[v] != std::numeric_limits<Index>::max()) first_write_order_.push_back(static_cast<Index>(v));
  std::stable_sort(first_write_order_.begin(), first_write_order_.end(),
                   [this](Index a, Index b) { return first_writer_[a] < first_writer_[b]; });
}

void Pattern::fill_inner(SlotIndex* inner, Index first, Index last) const {
  for (std::size_t b = static_cast<std::size_t>(first); b < static_cast<std::size_t>(last); ++b)
    for (int c = 0; c < 3; ++c) {
      SlotIndex k = outer_[3 * b + c];
      for (std::int64_t j = block_start_[b]; j < block_start_[b + 1]; ++j) {
        const Index a = block_rows_[j];
        const int rows = (static_cast<std::size_t>(a) == b) ? c + 1 : 3;
        for (int r = 0; r < rows; ++r) inner[k++] = 3 * a + r;
      }
    }
}

SlotIndex Pattern::find_block(Index a, Index b) const {
  if (a > b) std::swap(a, b);
  const auto first = block_rows_.begin() + block_start_[b], last = block_rows_.begin() + block_start_[b + 1];
  const auto it = std::lower_bound(first, last, a);
  if (it == last || *it != a) return -1;
  if (a == b) return diagonal_base_[b];
  return outer_[3 * static_cast<std::size_t>(b)] + 3 * static_cast<SlotIndex>(it - first);
}

}  // namespace hinge::fast
