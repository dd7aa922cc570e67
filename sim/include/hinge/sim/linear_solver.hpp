// hinge/sim/linear_solver.hpp: the sparse symmetric solvers of Newton's systems, on the upper triangle:
// CHOLMOD's simplicial LDL^T (SuiteSparse, through Eigen's CholmodSupport; simplicial, so no BLAS and no
// threads: results do not depend on the thread count) or Eigen's SimplicialLDLT. Both factor LDL^T
// without pivoting, which also takes the indefinite matrices of the "exact" Hessian treatment when no
// pivot vanishes; a failed factorization is reported, not thrown (the caller shifts and retries).
#pragma once

#include <Eigen/SparseCore>
#include <memory>

#include "hinge/sim/scene.hpp"

namespace hinge::sim {

class SparseSolver {
 public:
  virtual ~SparseSolver() = default;
  // The structure of `upper` (fixed from then on): the fill-reducing ordering, once.
  virtual void analyze(const Eigen::SparseMatrix<double>& upper) = 0;
  // Numerical factorization; false if it failed (a zero pivot).
  virtual bool factorize(const Eigen::SparseMatrix<double>& upper) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) = 0;
};

std::unique_ptr<SparseSolver> make_sparse_solver(LinearSolver kind);

}  // namespace hinge::sim
