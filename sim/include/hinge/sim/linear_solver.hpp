// hinge/sim/linear_solver.hpp: the sparse symmetric positive definite solvers of Newton's systems, on the
// upper triangle. `cholmod`: SuiteSparse's CHOLMOD choosing its own method (supernodal LL^T, whose dense
// kernels are the BLAS's, where its flop count per nonzero of L is large, as on cloth; simplicial LL^T
// otherwise), its fill-reducing ordering chosen once by analyze(), and the BLAS held to one thread (so that
// no result depends on a thread count); `ldlt`: Eigen's SimplicialLDLT, the alternative. factorize() says
// whether the matrix is positive definite: CHOLMOD stops at the first non-positive pivot
// (quick_return_if_not_posdef), LDL^T's D is checked, so a matrix that is not is never solved with.
#pragma once

#include <Eigen/SparseCore>
#include <memory>
#include <string>

#include "hinge/sim/scene.hpp"

namespace hinge::sim {

class SparseSolver {
 public:
  virtual ~SparseSolver() = default;
  // The structure of `upper` (fixed from then on): the fill-reducing ordering and the symbolic factor, once.
  virtual void analyze(const Eigen::SparseMatrix<double>& upper) = 0;
  // Numerical factorization; false if the matrix is not positive definite (to working precision).
  virtual bool factorize(const Eigen::SparseMatrix<double>& upper) = 0;
  // x = A^-1 b with the last successful factorization.
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) = 0;
  // What factors (summary.json's "linear_solver"): "cholmod supernodal LL^T", "cholmod simplicial LL^T" or
  // "eigen simplicial LDL^T"; known after analyze().
  virtual std::string name() const = 0;
};

std::unique_ptr<SparseSolver> make_sparse_solver(LinearSolver kind);

// Holds the BLAS that CHOLMOD's supernodal kernels call (OpenBLAS, when it is the system's libblas.so.3) to
// one thread, whatever OPENBLAS_NUM_THREADS says; a no-op for a BLAS without threads.
void hold_blas_to_one_thread();

}  // namespace hinge::sim
