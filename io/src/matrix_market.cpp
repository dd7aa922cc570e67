// Matrix Market input and output (hinge/io/matrix_market.hpp).
#include "hinge/io/matrix_market.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <limits>
#include <ostream>
#include <sstream>
#include <vector>

#include "hinge/core/errors.hpp"
#include "hinge/io/number.hpp"

namespace hinge::io {

void write_matrix_market(std::ostream& out, const Eigen::SparseMatrix<double>& upper, const std::string& comment) {
  out << "%%MatrixMarket matrix coordinate real symmetric\n"
      << "% " << comment << '\n'
      << upper.rows() << ' ' << upper.cols() << ' ' << upper.nonZeros() << '\n';
  std::string line;
  for (Eigen::Index c = 0; c < upper.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(upper, c); it; ++it) {
      line.clear();
      line += std::to_string(it.col() + 1);  // (row <= col) stored; (col, row) is in the lower triangle
      line += ' ';
      line += std::to_string(it.row() + 1);
      line += ' ';
      append_double(line, it.value());
      line += '\n';
      out << line;
    }
}

Eigen::SparseMatrix<double> read_matrix_market(std::istream& in, const std::string& name, Eigen::Index n) {
  std::string header;
  std::getline(in, header);
  std::string lower = header;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (lower.rfind("%%matrixmarket matrix coordinate real", 0) != 0)
    throw InputError(name + ": expected %%MatrixMarket matrix coordinate real symmetric|general");
  const bool symmetric = lower.find("symmetric") != std::string::npos;
  std::string text;
  while (std::getline(in, text) && (text.empty() || text[0] == '%')) {
  }
  long long rows = 0, cols = 0, count = 0;
  std::istringstream size(text);
  if (!(size >> rows >> cols >> count) || rows != n || cols != n || count < 0)
    throw InputError(name + ": expected a " + std::to_string(n) + " x " + std::to_string(n) + " matrix");
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(std::min<long long>(count, 1 << 24)));
  for (long long k = 0; k < count; ++k) {
    long long i = 0, j = 0;
    std::string value;
    if (!(in >> i >> j >> value) || i < 1 || j < 1 || i > n || j > n)
      throw InputError(name + ": entry " + std::to_string(k + 1) + " is unreadable or out of range");
    double v = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc() || end != value.data() + value.size())
      v = std::numeric_limits<double>::quiet_NaN();  // counted as non-finite
    const auto r = static_cast<Eigen::Index>(std::min(i, j) - 1), c = static_cast<Eigen::Index>(std::max(i, j) - 1);
    entries.emplace_back(r, c, symmetric || i == j ? v : v / 2);
  }
  Eigen::SparseMatrix<double> upper(n, n);
  upper.setFromTriplets(entries.begin(), entries.end());
  return upper;
}

Eigen::SparseMatrix<double> read_matrix_market(const std::string& path, Eigen::Index n) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read candidate Hessian " + path);
  return read_matrix_market(in, path, n);
}

}  // namespace hinge::io
