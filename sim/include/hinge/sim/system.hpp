// hinge/sim/system.hpp: the structure of Newton's linear systems. The Hessian of the total potential over
// all 3n coordinates (global index 3 v + c, as everywhere in hinge) is kept as its upper triangle (row <=
// col) in compressed columns, with a structure built once per mesh from the stencils of the effects the
// scene names (Couplings): the diagonal always (inertia, gravity, load and damping need no more), every
// vertex's 3 x 3 block for the sphere, every pair of vertices that share a face for stretching and
// bending, and the two opposite vertices of every hinge for bending. Effects add into its values through
// slots found once (element_slots). Pinned vertices' coordinates are removed from the system, not
// penalized: Reduction maps the full matrix and gradient onto the free coordinates (a copy without pins).
#pragma once

#include <Eigen/SparseCore>
#include <span>
#include <vector>

#include "hinge/core/mesh.hpp"

namespace hinge::sim {

using Slot = std::ptrdiff_t;  // index into the values of the upper triangle; -1: none

// Which blocks the named effects couple (effects.cpp: couplings(scene)).
struct Couplings {
  bool vertex_blocks = true;  // each vertex's 3 x 3 block (else its diagonal only)
  bool faces = true;          // the vertex pairs of every face
  bool hinges = true;         // the opposite vertices x0, x3 of every hinge
};

class Sparsity {
 public:
  explicit Sparsity(const Topology& topology, Couplings couplings = {});

  // Zero values with the fixed structure, 3n x 3n, upper triangle.
  const Eigen::SparseMatrix<double>& structure() const { return structure_; }
  Eigen::Index size() const { return structure_.rows(); }
  Slot nonzeros() const { return structure_.nonZeros(); }
  // The slot of entry (row, col), row <= col; -1 if the structure lacks it.
  Slot slot(Eigen::Index row, Eigen::Index col) const;
  // For an element on `vertices` (k of them), the (3k)^2 slots of its local matrix, column-major: entry
  // (i, j) of the local matrix goes to slot[i + 3k j] when its global row <= global column, and -1 where
  // the symmetric entry (j, i) carries it. Throws std::logic_error if the structure lacks an entry.
  std::vector<Slot> element_slots(std::span<const Index> vertices) const;

 private:
  Eigen::SparseMatrix<double> structure_;
};

// Adds the symmetric local matrix `local` ((3k)^2 values, column-major) into `values` through `slots`
// (from element_slots).
void scatter(std::span<const double> local, std::span<const Slot> slots, std::span<double> values);

// The free coordinates: those of vertices not pinned.
class Reduction {
 public:
  // Without pinned vertices the reduced system is the full one: reduce_* copy, expand_vector copies.
  Reduction(const Sparsity& sparsity, std::span<const Index> pinned_vertices);
  Eigen::Index free_count() const { return static_cast<Eigen::Index>(free_.size()); }
  bool is_free(Eigen::Index dof) const { return index_[static_cast<std::size_t>(dof)] >= 0; }
  // The matrix on the free coordinates (upper triangle), its structure fixed: reduce() overwrites values.
  Eigen::SparseMatrix<double>& matrix() { return reduced_; }
  // Copies the full matrix's values (sparsity's slots) into matrix(), and the free entries of `full`
  // (3n) into `free` (resized).
  void reduce_matrix(std::span<const double> values);
  void reduce_vector(const Eigen::VectorXd& full, Eigen::VectorXd& free) const;
  // The full vector (3n, zero on pinned coordinates) of a free one.
  void expand_vector(const Eigen::VectorXd& free, Eigen::VectorXd& full) const;

 private:
  std::vector<Eigen::Index> index_;  // dof -> free index or -1
  std::vector<Eigen::Index> free_;   // free index -> dof
  std::vector<Slot> target_;         // full slot -> reduced slot or -1
  bool identity_ = false;            // no pins
  Eigen::SparseMatrix<double> reduced_;
};

}  // namespace hinge::sim
