// hinge/fast/pattern.hpp: the block sparsity of a mesh's bending Hessian, built once per topology, with
// the position of every 3 x 3 block that Algorithm 2 writes precomputed, so that an evaluation adds
// straight into the values array: no searching, no allocation per call.
//
// The matrix is the upper triangle (row <= col) of the 3n x 3n energy Hessian, global index 3 v + c, in
// Eigen's compressed column layout (the convention of hinge::reference::assemble, so that the two can be
// compared entry by entry). Its nonzero blocks are those of the reference's hinge-by-hinge assembly: for
// every hinge (x0, x1, x2, x3) the 10 blocks among its four vertices (H03 included: psi'' grad theta
// grad theta^T fills it), upper triangles of the diagonal blocks only.
//
// Layout. Column vertex b lists its row vertices a < b in increasing order (K_b of them) and then itself;
// each of its three columns 3b + c holds 3 K_b off-diagonal entries and c + 1 diagonal ones:
//
//     column 3b+c:  [ rows 3a_0 .. 3a_0+2 | rows 3a_1 .. | ... | rows 3b .. 3b+c ]
//
// so entry (r, c) of the off-diagonal block (a_p, b) sits at outer[3b + c] + 3p + r, and entry (r, c),
// r <= c, of the diagonal block of b at outer[3b + c] + 3 K_b + r. A block is named by its `base`, the
// position of its entry (0, 0); with `stride` = 3 K_b + 1 (the length of column 3b) entry (r, c) is at
//     base + c stride + (c == 2) + r.
#pragma once

#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <vector>

#include "hinge/core/mesh.hpp"

namespace hinge::fast {

// Which of the two faces of an interior edge takes the conditional transpose (the paper's dagger, eq. (7))
// and owns the hinge's per-edge terms (grad theta, the force and psi'' grad theta grad theta^T):
// first_face: Edge::face[0], where the edge runs a -> b, counter-clockwise (the paper's choice, and the
// default); second_face: Edge::face[1]. In exact arithmetic both give the same Hessian.
enum class EdgeOrientation { first_face, second_face };

using SlotIndex = std::int32_t;  // Eigen::SparseMatrix's default StorageIndex: at most 2^31 - 1 entries

class Pattern {
 public:
  // A hinge as the face that owns it sees it (Algorithm 2, lines 15-20).
  // (Which face owns it and its local edge there: Face::owns of the face.)
  struct OwnedHinge {
    Index other_face = -1;   // the face across the edge
    Index s = -1;            // its vertex opposite the edge
    SlotIndex slot_ps = -1;  // blocks (p, s), (q, s), (r, s), p, q, r the owner's vertices k, k+1, k+2
    SlotIndex slot_qs = -1;  // for the edge k (its base; -1 when the two vertices coincide: a diagonal block)
    SlotIndex slot_rs = -1;
  };
  // One face: its vertices, for each local edge i (opposite vertex i) the hinge (-1 on the boundary)
  // and the base of the block between its two vertices, and which of its hinges it owns (bit i).
  struct Face {
    std::array<Index, 3> v{};
    std::array<Index, 3> hinge{-1, -1, -1};
    std::array<SlotIndex, 3> edge_slot{-1, -1, -1};
    unsigned owns = 0;
    // Which of its block writes, in the assembly's order, is the first one into its block: that write
    // stores instead of adding, so the values need no zeroing (bits: first_write_bit()).
    std::uint32_t first = 0;
    Index lowest = 0, highest = -1;  // range of every vertex it writes to (highest -1: writes nothing)
  };
  // The bit of Face::first for a face's writes: the diagonal block of its vertex i, its block off[i]
  // (vertices i, i+1), and for its owned edge k the blocks (s, s), (p, s), (q, s), (r, s).
  static constexpr int diagonal_bit(int i) { return i; }
  static constexpr int edge_bit(int i) { return 3 + i; }
  static constexpr int hinge_bit(int k, int which) { return 6 + 4 * k + which; }

  Pattern() = default;
  // Throws InputError if the matrix would have 2^31 entries or more.
  explicit Pattern(const Topology& topology, EdgeOrientation orientation = EdgeOrientation::first_face);

  Eigen::Index size() const { return 3 * static_cast<Eigen::Index>(vertex_count_); }
  std::int64_t nonzeros() const { return outer_.empty() ? 0 : outer_.back(); }
  EdgeOrientation orientation() const { return orientation_; }
  std::size_t vertex_count() const { return vertex_count_; }

  // Eigen's outer index array (3n + 1 column starts).
  const std::vector<SlotIndex>& outer() const { return outer_; }
  // The compressed structure, every value zero (returned by value: named return value, no copy).
  template <class Scalar>
  Eigen::SparseMatrix<Scalar> make_matrix() const;
  // The same with only the outer index array written: the row indices must then be written by
  // fill_inner for every column vertex, and the values (left as allocated) by the caller. For an
  // assembly that writes both in parallel, each thread the columns it owns.
  template <class Scalar>
  Eigen::SparseMatrix<Scalar> allocate_matrix() const;
  // The row indices of the columns of vertices [first, last) into `inner` (a matrix of this pattern).
  void fill_inner(SlotIndex* inner, Index first, Index last) const;
  // Whether `m` has exactly this structure (then an evaluation can overwrite its values).
  template <class Scalar>
  bool matches(const Eigen::SparseMatrix<Scalar>& m) const;

  // Block level: column vertex b's row vertices are block_rows()[block_start()[b] .. block_start()[b+1]),
  // increasing, the last one b itself (when b is in any hinge).
  const std::vector<std::int64_t>& block_start() const { return block_start_; }
  const std::vector<Index>& block_rows() const { return block_rows_; }
  // Base of block (a, b), a <= b, by binary search (for users; Algorithm 2 never searches).
  SlotIndex find_block(Index a, Index b) const;
  // Base and stride of the diagonal block of v, and the stride of column vertex v (3 K_v + 1).
  SlotIndex diagonal_base(Index v) const { return diagonal_base_[v]; }
  SlotIndex stride(Index v) const { return stride_[v]; }
  const std::vector<SlotIndex>& diagonal_bases() const { return diagonal_base_; }
  const std::vector<SlotIndex>& strides() const { return stride_; }
  // Position of entry (r, c) of the block with `base` whose column vertex is b.
  SlotIndex entry(SlotIndex base, Index b, int r, int c) const { return base + c * stride_[b] + (c == 2) + r; }

  const std::vector<Face>& faces() const { return faces_; }
  // The column vertices in the order of the first face that writes into their columns (ties by vertex),
  // and that face: the assembly prefetches a vertex's columns a few faces before that one (assemble.hpp).
  const std::vector<Index>& first_write_order() const { return first_write_order_; }
  const std::vector<Index>& first_writer() const { return first_writer_; }
  // Per hinge (Topology::hinges order): its owner's view.
  const std::vector<OwnedHinge>& hinges() const { return hinges_; }

  // The values as raw 3 x 3 blocks (column-major, 9 per block; diagonal blocks with their lower
  // triangle mirrored), in the order of block_rows(): one way to hand them to block-sparse solvers.
  template <class Scalar>
  std::vector<std::array<Scalar, 9>> blocks(const Scalar* values) const;

 private:
  std::size_t vertex_count_ = 0;
  EdgeOrientation orientation_ = EdgeOrientation::first_face;
  std::vector<SlotIndex> outer_;
  std::vector<std::int64_t> block_start_;
  std::vector<Index> block_rows_;
  std::vector<SlotIndex> diagonal_base_, stride_;
  std::vector<Face> faces_;
  std::vector<OwnedHinge> hinges_;
  std::vector<Index> first_write_order_, first_writer_;
};

template <class Scalar>
Eigen::SparseMatrix<Scalar> Pattern::allocate_matrix() const {
  Eigen::SparseMatrix<Scalar> m(size(), size());
  m.resizeNonZeros(static_cast<Eigen::Index>(nonzeros()));
  std::copy(outer_.begin(), outer_.end(), m.outerIndexPtr());
  return m;
}

template <class Scalar>
Eigen::SparseMatrix<Scalar> Pattern::make_matrix() const {
  Eigen::SparseMatrix<Scalar> m = allocate_matrix<Scalar>();
  fill_inner(m.innerIndexPtr(), 0, static_cast<Index>(vertex_count_));
  std::fill(m.valuePtr(), m.valuePtr() + nonzeros(), Scalar(0));
  return m;
}

template <class Scalar>
bool Pattern::matches(const Eigen::SparseMatrix<Scalar>& m) const {
  if (m.rows() != size() || m.cols() != size() || !m.isCompressed() || m.nonZeros() != nonzeros()) return false;
  return std::equal(outer_.begin(), outer_.end(), m.outerIndexPtr());
}

template <class Scalar>
std::vector<std::array<Scalar, 9>> Pattern::blocks(const Scalar* values) const {
  std::vector<std::array<Scalar, 9>> out(block_rows_.size());
  for (std::size_t b = 0; b < vertex_count_; ++b)
    for (std::int64_t j = block_start_[b]; j < block_start_[b + 1]; ++j) {
      const Index a = block_rows_[j];
      const bool diagonal = static_cast<std::size_t>(a) == b;
      const SlotIndex base =
          diagonal ? diagonal_base_[b] : outer_[3 * b] + 3 * static_cast<SlotIndex>(j - block_start_[b]);
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) {
          const bool upper = !diagonal || r <= c;
          out[j][3 * c + r] = upper ? values[entry(base, static_cast<Index>(b), r, c)]
                                    : values[entry(base, static_cast<Index>(b), c, r)];
        }
    }
  return out;
}

}  // namespace hinge::fast
