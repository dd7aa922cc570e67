// Unit tests of the Matrix Market writer of `hinge hessian --out` and the reader of `hinge conform`
// (io/src/matrix_market.cpp; docs/contract.md 9.2): `coordinate real symmetric` written (lower triangle),
// `symmetric` or `general` read into the upper triangle, 1-based indices, every value read back exactly
// (zeros compare as values: -0.0 equals 0.0), and errors "FILE: why" for another header, another size, an
// index out of range or a truncated entry list (messages as docs/testing.md, "Bad input" 47-49, shows them).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "hinge/core/errors.hpp"
#include "hinge/io/matrix_market.hpp"

namespace hinge {
namespace {

using Sparse = Eigen::SparseMatrix<double>;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

std::string g17(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

Sparse read_text(const std::string& text, Eigen::Index n, const std::string& name = "H.mtx") {
  std::istringstream in(text);
  return io::read_matrix_market(in, name, n);
}

// The message of the InputError that reading `text` throws; fails the test when it throws nothing.
std::string read_error(const std::string& text, Eigen::Index n, const std::string& name = "H.mtx") {
  try {
    read_text(text, n, name);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no hinge::InputError for:\n" << text;
  return {};
}

// Every value of `m`, dense, and a check that nothing is stored below the diagonal.
std::vector<double> dense_upper(const Sparse& m) {
  std::vector<double> d(static_cast<std::size_t>(m.rows() * m.cols()), 0.0);
  for (Eigen::Index c = 0; c < m.outerSize(); ++c)
    for (Sparse::InnerIterator it(m, c); it; ++it) {
      EXPECT_LE(it.row(), it.col()) << "an entry below the diagonal";
      d[static_cast<std::size_t>(it.row() * m.cols() + it.col())] += it.value();
    }
  return d;
}

// The same double, or two zeros (docs/contract.md: -0.0 equals 0.0 as values); == is bit equality for
// every other non-NaN double.
void expect_same_values(const Sparse& expected, const Sparse& got) {
  ASSERT_EQ(got.rows(), expected.rows());
  ASSERT_EQ(got.cols(), expected.cols());
  const std::vector<double> a = dense_upper(expected), b = dense_upper(got);
  int mismatches = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!(a[k] == b[k]) && mismatches++ < 5)
      ADD_FAILURE() << "(" << k / static_cast<std::size_t>(got.cols()) << ", "
                    << k % static_cast<std::size_t>(got.cols()) << "): expected " << g17(a[k]) << " (0x" << std::hex
                    << bits(a[k]) << "), got " << g17(b[k]) << " (0x" << bits(b[k]) << std::dec << ")";
  EXPECT_EQ(mismatches, 0);
}

double value_at(const Sparse& m, Eigen::Index r, Eigen::Index c) {
  return dense_upper(m)[static_cast<std::size_t>(r * m.cols() + c)];
}

std::vector<double> hard_doubles() {
  using L = std::numeric_limits<double>;
  return {L::denorm_min(),
          -L::denorm_min(),
          3 * L::denorm_min(),
          L::min() - L::denorm_min(),
          L::min(),
          -L::min(),
          L::max(),
          -L::max(),
          std::nextafter(L::max(), 0.0),
          std::nextafter(1.0, 0.0),
          std::nextafter(2.0, 0.0),
          -std::nextafter(1024.0, 0.0),
          std::nextafter(std::ldexp(1.0, 53), 0.0),
          std::nextafter(1.0, 2.0),
          0.1,
          0.30000000000000004,
          1.0 / 3.0,
          1e23,
          2.2250738585072011e-308,
          123456789012345678.0,
          -1.2345678901234567e-300,
          5e-310,
          -0.0,
          0.0};
}

// A random n x n upper triangle with about `per_column` entries per column, hard doubles first, then
// random finite bit patterns (a share of them subnormal).
Sparse random_upper(Eigen::Index n, int per_column, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::vector<double> hard = hard_doubles();
  std::vector<Eigen::Triplet<double>> t;
  std::set<std::pair<Eigen::Index, Eigen::Index>> used;
  std::size_t k = 0;
  for (Eigen::Index c = 0; c < n; ++c) {
    for (int e = 0; e < per_column; ++e) {
      const Eigen::Index r = e == 0 ? c : static_cast<Eigen::Index>(rng() % static_cast<std::uint64_t>(c + 1));
      if (!used.insert({r, c}).second) continue;
      double v;
      if (k < hard.size()) {
        v = hard[k];
      } else {
        do {
          std::uint64_t b = rng();
          if (k % 5 == 0) b &= 0x800f'ffff'ffff'ffffULL;
          v = std::bit_cast<double>(b);
        } while (!std::isfinite(v));
      }
      ++k;
      t.emplace_back(r, c, v);
    }
  }
  Sparse m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

std::string written(const Sparse& upper, const std::string& comment = "test") {
  std::ostringstream out;
  io::write_matrix_market(out, upper, comment);
  return out.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

const std::string kSymmetric = "%%MatrixMarket matrix coordinate real symmetric\n";
const std::string kGeneral = "%%MatrixMarket matrix coordinate real general\n";

// ---------------------------------------------------------------------------------------------------
// Writing

TEST(MatrixMarketWrite, WritesTheHeaderTheCommentTheSizeAndTheLowerTriangle) {
  Sparse upper(6, 6);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 1.0},    {0, 5, 0.1},  {1, 1, -0.0},
                                           {2, 4, 5e-324}, {3, 3, -2.5}, {4, 5, 1e300}};
  upper.setFromTriplets(t.begin(), t.end());
  const std::vector<std::string> lines = lines_of(written(upper, "the Hessian of E"));
  ASSERT_EQ(lines.size(), 3u + t.size());
  EXPECT_EQ(lines[0], "%%MatrixMarket matrix coordinate real symmetric");
  EXPECT_EQ(lines[1], "% the Hessian of E");
  EXPECT_EQ(lines[2], "6 6 6");
  // Each stored (row <= col) entry once, as (col + 1, row + 1): the lower triangle, 1-based.
  std::set<std::tuple<long, long, std::string>> got, expected;
  for (std::size_t k = 3; k < lines.size(); ++k) {
    std::istringstream in(lines[k]);
    long i = 0, j = 0;
    std::string v, rest;
    ASSERT_TRUE(in >> i >> j >> v) << lines[k];
    EXPECT_FALSE(in >> rest) << "three fields per line: " << lines[k];
    EXPECT_GE(i, j) << "lower triangle: " << lines[k];
    got.insert({i, j, v});
  }
  for (const auto& e : t) expected.insert({static_cast<long>(e.col() + 1), static_cast<long>(e.row() + 1), ""});
  std::set<std::tuple<long, long, std::string>> got_positions;
  for (const auto& [i, j, v] : got) got_positions.insert({i, j, ""});
  EXPECT_EQ(got_positions, expected);
  // Values as io/number.hpp writes them: shortest, and always with a point or an exponent.
  EXPECT_TRUE(got.count({1, 1, "1.0"}));
  EXPECT_TRUE(got.count({6, 1, "0.1"}));
  EXPECT_TRUE(got.count({2, 2, "-0.0"}));
  EXPECT_TRUE(got.count({5, 3, "5e-324"}));
  EXPECT_TRUE(got.count({4, 4, "-2.5"}));
  EXPECT_TRUE(got.count({6, 5, "1e+300"}));
}

TEST(MatrixMarketWrite, AnEmptyMatrixHasASizeLineAndNoEntries) {
  const std::vector<std::string> lines = lines_of(written(Sparse(9, 9), "none"));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[2], "9 9 0");
  const Sparse back = read_text(written(Sparse(9, 9)), 9);
  EXPECT_EQ(back.rows(), 9);
  for (double v : dense_upper(back)) EXPECT_EQ(v, 0.0);
}

// ---------------------------------------------------------------------------------------------------
// Round trips

TEST(MatrixMarketRead, SymmetricCoordinateRoundTripsBitForBit) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const Eigen::Index n = static_cast<Eigen::Index>(3 * (10 + 7 * seed));
    const Sparse upper = random_upper(n, 6, seed);
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same_values(upper, read_text(written(upper), n));
  }
}

TEST(MatrixMarketRead, SeventeenDigitValuesFromAnotherWriterReadBackBitForBit) {
  // Another program writing %.17g, in either triangle: the same doubles.
  const Eigen::Index n = 60;
  const Sparse upper = random_upper(n, 5, 9);
  std::string text = kSymmetric + "% written with %.17g\n" + std::to_string(n) + " " + std::to_string(n) + " " +
                     std::to_string(upper.nonZeros()) + "\n";
  bool lower = false;
  for (Eigen::Index c = 0; c < upper.outerSize(); ++c)
    for (Sparse::InnerIterator it(upper, c); it; ++it) {
      const Eigen::Index i = (lower ? it.col() : it.row()) + 1, j = (lower ? it.row() : it.col()) + 1;
      text += std::to_string(i) + " " + std::to_string(j) + " " + g17(it.value()) + "\n";
      lower = !lower;
    }
  expect_same_values(upper, read_text(text, n));
}

TEST(MatrixMarketRead, ReadsEntriesFromEitherTriangleOfASymmetricFileIntoTheUpperOne) {
  const Sparse m = read_text(kSymmetric + "3 3 4\n1 1 2.0\n3 1 0.5\n2 3 -1.25\n2 2 7e-310\n", 3);
  EXPECT_EQ(value_at(m, 0, 0), 2.0);
  EXPECT_EQ(value_at(m, 0, 2), 0.5);
  EXPECT_EQ(value_at(m, 1, 2), -1.25);
  EXPECT_EQ(value_at(m, 1, 1), 7e-310);
  EXPECT_EQ(value_at(m, 2, 0), 0.0) << "nothing stored below the diagonal";
  EXPECT_EQ(m.nonZeros(), 4);
}

TEST(MatrixMarketRead, AGeneralFileAveragesTheTwoTriangles) {
  // matrix_market.hpp: "general: (i, j) and (j, i) averaged"; the diagonal as it is.
  const Sparse m = read_text(kGeneral + "3 3 5\n1 2 1.0\n2 1 3.0\n3 3 -4.5\n1 3 0.25\n3 1 0.25\n", 3);
  EXPECT_EQ(value_at(m, 0, 1), 2.0);
  EXPECT_EQ(value_at(m, 2, 2), -4.5);
  EXPECT_EQ(value_at(m, 0, 2), 0.25);
}

TEST(MatrixMarketRead, AGeneralFileWithEqualTrianglesReadsNormalValuesExactly) {
  // A symmetric matrix written as general, both triangles: each value back exactly, the extremes included
  // (halving before adding cannot overflow at max).
  const std::vector<double> values = {std::numeric_limits<double>::max(),
                                      -std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::min(),
                                      std::nextafter(1.0, 0.0),
                                      0.1,
                                      1.0 / 3.0,
                                      0.30000000000000004,
                                      -1.2345678901234567e-300,
                                      1e23};
  const Eigen::Index n = static_cast<Eigen::Index>(values.size()) + 1;
  std::string text =
      kGeneral + std::to_string(n) + " " + std::to_string(n) + " " + std::to_string(2 * values.size()) + "\n";
  for (std::size_t k = 0; k < values.size(); ++k) {
    text += "1 " + std::to_string(k + 2) + " " + g17(values[k]) + "\n";
    text += std::to_string(k + 2) + " 1 " + g17(values[k]) + "\n";
  }
  const Sparse m = read_text(text, n);
  for (std::size_t k = 0; k < values.size(); ++k) {
    const double got = value_at(m, 0, static_cast<Eigen::Index>(k + 1));
    EXPECT_EQ(bits(got), bits(values[k])) << "wrote " << g17(values[k]) << ", read " << g17(got);
  }
}

TEST(MatrixMarketRead, DuplicateEntriesAreSummed) {
  const Sparse m = read_text(kSymmetric + "3 3 4\n2 1 1.5\n1 2 0.25\n3 3 1.0\n3 3 2.0\n", 3);
  EXPECT_EQ(value_at(m, 0, 1), 1.75);
  EXPECT_EQ(value_at(m, 2, 2), 3.0);
}

TEST(MatrixMarketRead, NegativeZeroReadsAsTheValueZero) {
  const Sparse m = read_text(kSymmetric + "3 3 2\n1 1 -0.0\n3 2 -0\n", 3);
  EXPECT_EQ(value_at(m, 0, 0), 0.0);
  EXPECT_EQ(value_at(m, 1, 2), 0.0);
}

TEST(MatrixMarketRead, TheHeaderIsCaseInsensitiveAndCommentsAndBlankLinesPrecedeTheSize) {
  const Sparse m = read_text(
      "%%matrixmarket MATRIX Coordinate REAL Symmetric\n"
      "% a comment\n"
      "\n"
      "%another\n"
      "%\n"
      "3 3 1\n"
      "3 3 4.0\n",
      3);
  EXPECT_EQ(value_at(m, 2, 2), 4.0);
}

TEST(MatrixMarketRead, CrlfLineEndingsAndExtraWhitespaceAreRead) {
  const Sparse m = read_text(
      "%%MatrixMarket matrix coordinate real general\r\n"
      "% comment\r\n"
      "  3   3\t2  \r\n"
      "\t1 1   0.5 \r\n"
      "3  3 -2\r\n",
      3);
  EXPECT_EQ(value_at(m, 0, 0), 0.5);
  EXPECT_EQ(value_at(m, 2, 2), -2.0);
}

TEST(MatrixMarketRead, AValueThatIsNotANumberIsReadAsNaN) {
  // matrix_market.hpp: "a value that is not a number is read as NaN (for the caller to count as
  // non-finite)"; a value outside the range of double is not a double either.
  for (const std::string bad : {"abc", "1.0x", "1,5", "0x1p3", "--1", "1e400", "-1e400", "nan", "NaN"}) {
    const Sparse m = read_text(kSymmetric + "3 3 2\n1 1 1.0\n2 1 " + bad + "\n", 3);
    EXPECT_TRUE(std::isnan(value_at(m, 0, 1))) << bad << " read as " << g17(value_at(m, 0, 1));
    EXPECT_EQ(value_at(m, 0, 0), 1.0) << bad;
  }
  // Infinity text is no finite value either.
  for (const std::string inf : {"inf", "-inf", "infinity"}) {
    const Sparse m = read_text(kSymmetric + "3 3 1\n2 1 " + inf + "\n", 3);
    EXPECT_FALSE(std::isfinite(value_at(m, 0, 1))) << inf;
  }
}

// ---------------------------------------------------------------------------------------------------
// Rejections (docs/testing.md, Bad input 47-49: the messages, naming the file)

TEST(MatrixMarketRead, RejectsAHeaderThatIsNotCoordinateRealSymmetricOrGeneral) {
  const std::string expected = "H.mtx: expected %%MatrixMarket matrix coordinate real symmetric|general";
  for (const std::string header :
       {"", "%%MatrixMarket matrix array real general", "%%MatrixMarket matrix coordinate complex symmetric",
        "%%MatrixMarket matrix coordinate integer general", "%%MatrixMarket matrix coordinate pattern symmetric",
        "%%MatrixMarket vector coordinate real general", "MatrixMarket matrix coordinate real symmetric", "% comment",
        "3 3 0", " %%MatrixMarket matrix coordinate real symmetric"}) {
    EXPECT_EQ(read_error(header + "\n3 3 1\n1 1 1.0\n", 3), expected) << header;
  }
  EXPECT_EQ(read_error("", 3), expected) << "an empty file";
  EXPECT_EQ(read_error("\n\n", 3, "other.mtx"),
            "other.mtx: expected %%MatrixMarket matrix coordinate real symmetric|general");
}

TEST(MatrixMarketRead, RejectsAnotherSizeNamingTheExpectedOne) {
  for (const std::string size : {"11 12 0", "12 11 0", "13 13 0", "4 4 0", "12 12", "12", "", "twelve 12 0", "12 12 -1",
                                 "12.5 12 0", "-12 -12 0"}) {
    EXPECT_EQ(read_error(kSymmetric + "% c\n" + size + "\n", 12), "H.mtx: expected a 12 x 12 matrix")
        << "'" << size << "'";
  }
  EXPECT_EQ(read_error(kSymmetric, 12), "H.mtx: expected a 12 x 12 matrix") << "no size line";
  EXPECT_EQ(read_error(kSymmetric + "% only comments\n%\n", 6, "m.mtx"), "m.mtx: expected a 6 x 6 matrix");
}

TEST(MatrixMarketRead, RejectsAnEntryOutOfRangeNamingTheEntry) {
  // The message names the entry's position in the entry list (1-based).
  for (const std::string bad : {"0 1", "1 0", "4 1", "1 4", "-1 2", "2 -1", "4 4", "99999999999999999999 1"}) {
    EXPECT_EQ(read_error(kSymmetric + "3 3 3\n1 1 1.0\n2 2 1.0\n" + bad + " 1.0\n", 3),
              "H.mtx: entry 3 is unreadable or out of range")
        << bad;
  }
  EXPECT_EQ(read_error(kGeneral + "% c\n3 3 2\n4 4 1.0\n1 1 1.0\n", 3), "H.mtx: entry 1 is unreadable or out of range");
}

TEST(MatrixMarketRead, RejectsATruncatedEntryListNamingTheFirstMissingEntry) {
  EXPECT_EQ(read_error(kSymmetric + "3 3 3\n1 1 1.0\n2 2 1.0\n", 3), "H.mtx: entry 3 is unreadable or out of range");
  EXPECT_EQ(read_error(kSymmetric + "3 3 3\n1 1 1.0\n2 2", 3), "H.mtx: entry 2 is unreadable or out of range");
  EXPECT_EQ(read_error(kSymmetric + "3 3 1\n", 3), "H.mtx: entry 1 is unreadable or out of range");
  EXPECT_EQ(read_error(kSymmetric + "3 3 2\n1 1 1.0\nx 2 1.0\n", 3), "H.mtx: entry 2 is unreadable or out of range");
  EXPECT_EQ(read_error(kSymmetric + "3 3 2\n1 1 1.0\n1.5 2 1.0\n", 3), "H.mtx: entry 2 is unreadable or out of range");
}

TEST(MatrixMarketRead, ReadsAFileByPathAndNamesAMissingOne) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("hinge_matrix_market_test_" + std::to_string(std::random_device{}()) + ".mtx");
  const Sparse upper = random_upper(12, 4, 21);
  {
    std::ofstream out(path, std::ios::binary);
    io::write_matrix_market(out, upper, "by path");
  }
  expect_same_values(upper, io::read_matrix_market(path.string(), 12));
  try {
    io::read_matrix_market(path.string(), 15);
    ADD_FAILURE() << "no error for another size";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": expected a 15 x 15 matrix");
  }
  std::filesystem::remove(path);
  try {
    io::read_matrix_market(path.string(), 12);
    ADD_FAILURE() << "no error for a missing file";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), path.string()));
  }
}

}  // namespace
}  // namespace hinge
