// The sparse solvers (hinge/sim/linear_solver.hpp).
#include "hinge/sim/linear_solver.hpp"

#include <dlfcn.h>

#include <Eigen/SparseCholesky>
#include <stdexcept>

extern "C" {
#include <suitesparse/cholmod.h>
}

namespace hinge::sim {
namespace {

// CHOLMOD on the upper triangle of a compressed-column matrix (stype 1), without copying it.
class Cholmod final : public SparseSolver {
 public:
  Cholmod() {
    hold_blas_to_one_thread();
    cholmod_start(&common_);
    common_.print = 0;                       // a failure is reported to the caller, not printed
    common_.supernodal = CHOLMOD_AUTO;       // supernodal where flops / nnz(L) >= supernodal_switch (40)
    common_.final_ll = 1;                    // simplicial LL^T too: it stops at a non-positive pivot
    common_.quick_return_if_not_posdef = 1;  // the supernodal factorization stops there as well
  }
  ~Cholmod() override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  Cholmod(const Cholmod&) = delete;
  Cholmod& operator=(const Cholmod&) = delete;

  void analyze(const Eigen::SparseMatrix<double>& upper) override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_sparse a = view(upper);
    factor_ = cholmod_analyze(&a, &common_);
    if (!factor_) throw std::runtime_error("CHOLMOD could not analyze the Hessian's structure");
    supernodal_ = factor_->is_super != 0;
  }
  bool factorize(const Eigen::SparseMatrix<double>& upper) override {
    cholmod_sparse a = view(upper);
    cholmod_factorize(&a, factor_, &common_);
    return common_.status == CHOLMOD_OK && factor_->minor == factor_->n;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override {
    cholmod_dense rhs{};
    rhs.nrow = rhs.d = static_cast<std::size_t>(b.size());
    rhs.ncol = 1;
    rhs.nzmax = rhs.nrow;
    rhs.x = const_cast<double*>(b.data());
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, factor_, &rhs, &common_);
    if (!x) throw std::runtime_error("CHOLMOD could not solve");
    Eigen::VectorXd out = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(x->x), b.size());
    cholmod_free_dense(&x, &common_);
    return out;
  }
  std::string name() const override { return supernodal_ ? "cholmod supernodal LL^T" : "cholmod simplicial LL^T"; }

 private:
  static cholmod_sparse view(const Eigen::SparseMatrix<double>& upper) {
    cholmod_sparse a{};
    a.nrow = a.ncol = static_cast<std::size_t>(upper.rows());
    a.nzmax = static_cast<std::size_t>(upper.nonZeros());
    a.p = const_cast<int*>(upper.outerIndexPtr());
    a.i = const_cast<int*>(upper.innerIndexPtr());
    a.x = const_cast<double*>(upper.valuePtr());
    a.stype = 1;  // the upper triangle holds the matrix
    a.itype = CHOLMOD_INT;
    a.xtype = CHOLMOD_REAL;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;
    return a;
  }

  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
  bool supernodal_ = false;
};

class EigenLdlt final : public SparseSolver {
 public:
  void analyze(const Eigen::SparseMatrix<double>& upper) override { f_.analyzePattern(upper); }
  bool factorize(const Eigen::SparseMatrix<double>& upper) override {
    f_.factorize(upper);
    return f_.info() == Eigen::Success && (f_.vectorD().array() > 0).all();
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override { return f_.solve(b); }
  std::string name() const override { return "eigen simplicial LDL^T"; }

 private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper> f_;
};

}  // namespace

void hold_blas_to_one_thread() {
  // OpenBLAS's own entry point, looked up at run time: present in its threaded and serial builds, absent
  // from the reference BLAS (which has no threads).
  using SetThreads = void (*)(int);
  if (auto* set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
}

std::unique_ptr<SparseSolver> make_sparse_solver(LinearSolver kind) {
  if (kind == LinearSolver::cholmod) return std::make_unique<Cholmod>();
  return std::make_unique<EigenLdlt>();
}

}  // namespace hinge::sim
