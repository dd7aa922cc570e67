// Fuzz target: the Matrix Market reader of `hinge conform --mesh --hessian` (hinge/io/matrix_market.hpp).
// The first byte chooses the expected size n (3 to 96, 3 per vertex); on success the matrix is n x n
// and upper triangular, as the reader promises.
#include <sstream>

#include "fuzz_target.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/matrix_market.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using hinge::fuzz::require;
  if (size == 0) return 0;
  const Eigen::Index n = 3 * (1 + data[0] % 32);
  std::istringstream in(hinge::fuzz::as_string(data + 1, size - 1));
  try {
    const Eigen::SparseMatrix<double> m = hinge::io::read_matrix_market(in, "fuzz.mtx", n);
    require(m.rows() == n && m.cols() == n, "a matrix of another size was accepted");
    for (Eigen::Index c = 0; c < m.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(m, c); it; ++it)
        require(it.row() <= it.col(), "an entry below the diagonal in the upper triangle");
  } catch (const hinge::InputError&) {
  }
  return 0;
}
