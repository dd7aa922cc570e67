// Google Benchmark: Newton's linear systems of `hinge simulate` (the matrices --dump-system writes as
// STEP-ITER.solved.mtx) factored and solved by CHOLMOD alone (its own calls, no code of hinge::sim: its
// supernodal and simplicial LL^T, AMD/METIS as CHOLMOD chooses, the BLAS on one thread) and by Eigen's
// SimplicialLDLT: what one factorization and solve costs, to hold the simulator's linear solve per
// factorization (summary.json: time_s.linear_solve / solver.factorizations) against (bench/README.md).
//   solver/<file>/cholmod_supernodal, cholmod_simplicial, eigen_ldlt
// Usage: sim_solver_bench FILE.solved.mtx [...] [Google Benchmark flags]; bench/sim_solvers.sh makes the
// files for the cloth-sphere at 21^2, 41^2 and 81^2 and prints the table.
#include <benchmark/benchmark.h>
#include <dlfcn.h>

#include <Eigen/SparseCholesky>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "hinge/io/matrix_market.hpp"

extern "C" {
#include <suitesparse/cholmod.h>
}

namespace {

using Matrix = Eigen::SparseMatrix<double>;

// The size on the Matrix Market file's size line.
Eigen::Index matrix_size(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '%') {
      long long rows = 0;
      std::istringstream(line) >> rows;
      return static_cast<Eigen::Index>(rows);
    }
  return 0;
}

cholmod_sparse view(const Matrix& upper) {
  cholmod_sparse a{};
  a.nrow = a.ncol = static_cast<std::size_t>(upper.rows());
  a.nzmax = static_cast<std::size_t>(upper.nonZeros());
  a.p = const_cast<int*>(upper.outerIndexPtr());
  a.i = const_cast<int*>(upper.innerIndexPtr());
  a.x = const_cast<double*>(upper.valuePtr());
  a.stype = 1, a.itype = CHOLMOD_INT, a.xtype = CHOLMOD_REAL, a.dtype = CHOLMOD_DOUBLE, a.sorted = 1, a.packed = 1;
  return a;
}

void cholmod(benchmark::State& state, const Matrix* upper, int method) {
  cholmod_common c;
  cholmod_start(&c);
  c.supernodal = method, c.final_ll = 1;
  cholmod_sparse a = view(*upper);
  cholmod_factor* L = cholmod_analyze(&a, &c);
  cholmod_dense* b = cholmod_ones(a.nrow, 1, CHOLMOD_REAL, &c);
  for (auto _ : state) {
    cholmod_factorize(&a, L, &c);
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, L, b, &c);
    benchmark::DoNotOptimize(x->x);
    cholmod_free_dense(&x, &c);
  }
  if (c.status != CHOLMOD_OK) state.SkipWithError("CHOLMOD: the matrix is not positive definite");
  state.counters["nnz_L"] = c.lnz;
  state.counters["flops"] = c.fl;
  state.SetLabel(L->is_super ? "supernodal" : "simplicial");
  cholmod_free_dense(&b, &c);
  cholmod_free_factor(&L, &c);
  cholmod_finish(&c);
}

void eigen_ldlt(benchmark::State& state, const Matrix* upper) {
  Eigen::SimplicialLDLT<Matrix, Eigen::Upper> f;
  f.analyzePattern(*upper);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(upper->rows());
  for (auto _ : state) {
    f.factorize(*upper);
    Eigen::VectorXd x = f.solve(b);
    benchmark::DoNotOptimize(x.data());
  }
}

}  // namespace

int main(int argc, char** argv) {
  // OpenBLAS on one thread, as the simulator holds it (hinge::sim::hold_blas_to_one_thread).
  using SetThreads = void (*)(int);
  if (auto* set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
  benchmark::Initialize(&argc, argv);
  static std::vector<Matrix> matrices;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) files.emplace_back(argv[i]);
  if (files.empty()) {
    std::fprintf(stderr, "usage: sim_solver_bench FILE.solved.mtx [...] (bench/sim_solvers.sh makes them)\n");
    return 2;
  }
  matrices.reserve(files.size());
  for (const auto& f : files) matrices.push_back(hinge::io::read_matrix_market(f, matrix_size(f)));
  for (std::size_t k = 0; k < files.size(); ++k) {
    const std::string name =
        "solver/" + std::filesystem::path(files[k]).parent_path().parent_path().filename().string();
    const Matrix* m = &matrices[k];
    benchmark::RegisterBenchmark((name + "/cholmod_supernodal").c_str(), cholmod, m, CHOLMOD_SUPERNODAL)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((name + "/cholmod_simplicial").c_str(), cholmod, m, CHOLMOD_SIMPLICIAL)
        ->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((name + "/eigen_ldlt").c_str(), eigen_ldlt, m)->Unit(benchmark::kMillisecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
