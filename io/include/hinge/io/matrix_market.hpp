// hinge/io/matrix_market.hpp: the mesh Hessian as a Matrix Market file (docs/contract.md, `hinge hessian
// --out`): `coordinate real symmetric` (or, read only, `general`), 1-based, 3n x 3n, global index 3 v + c.
// In memory the matrix is its upper triangle (row <= col, hinge/core/results.hpp); the file holds
// the same entries as the lower triangle (row >= col), as symmetric Matrix Market files conventionally do.
#pragma once

#include <Eigen/SparseCore>
#include <iosfwd>
#include <string>

namespace hinge::io {

// Writes `upper` (every number read back exactly), with `comment` as the second line ("% comment").
void write_matrix_market(std::ostream& out, const Eigen::SparseMatrix<double>& upper, const std::string& comment);

// Reads an n x n matrix (symmetric: entries from either triangle; general: (i, j) and (j, i) averaged) as
// its upper triangle; duplicate entries are summed; a value that is not a number is read as NaN (for the
// caller to count as non-finite). Throws hinge::InputError "FILE: why" for an unreadable file, another
// header, another size, an index out of range or a truncated entry list.
Eigen::SparseMatrix<double> read_matrix_market(const std::string& path, Eigen::Index n);
Eigen::SparseMatrix<double> read_matrix_market(std::istream& in, const std::string& name_for_errors, Eigen::Index n);

}  // namespace hinge::io
