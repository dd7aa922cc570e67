// The sparse solvers (hinge/sim/linear_solver.hpp).
#include "hinge/sim/linear_solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

namespace hinge::sim {
namespace {

template <class Factorization>
class EigenSolver final : public SparseSolver {
 public:
  EigenSolver() {
    if constexpr (requires { f_.cholmod(); })
      f_.cholmod().print = 0;  // a failed factorization is reported to the caller, not printed by CHOLMOD
  }
  void analyze(const Eigen::SparseMatrix<double>& upper) override { f_.analyzePattern(upper); }
  bool factorize(const Eigen::SparseMatrix<double>& upper) override {
    f_.factorize(upper);
    return f_.info() == Eigen::Success;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override { return f_.solve(b); }

 private:
  Factorization f_;
};

}  // namespace

std::unique_ptr<SparseSolver> make_sparse_solver(LinearSolver kind) {
  using Matrix = Eigen::SparseMatrix<double>;
  if (kind == LinearSolver::cholmod)
    return std::make_unique<EigenSolver<Eigen::CholmodSimplicialLDLT<Matrix, Eigen::Upper>>>();
  return std::make_unique<EigenSolver<Eigen::SimplicialLDLT<Matrix, Eigen::Upper>>>();
}

}  // namespace hinge::sim
