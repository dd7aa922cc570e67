// hinge/io/number.hpp: numbers written so that they read back exactly (docs/contract.md: "Every number any
// command writes reads back exactly").
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace hinge::io {

// Shortest decimal that reads back to exactly `x` (std::to_chars), with ".0" on integral values so
// that every number looks like a double ("1.0", "-0.0", "1e+300", "5e-324").
std::string format_double(double x);
void append_double(std::string& out, double x);

// "[a, b, ...]": `count` numbers as a JSON array, each as append_double writes it.
void append_array(std::string& out, const double* values, std::size_t count);

// A vector as text, one number per line (the gradient file of `hinge hessian --gradient`).
void write_numbers(std::ostream& out, const std::vector<double>& values);
// Whitespace-separated numbers read back (correctly rounded); a token that is not a number is read as NaN,
// for the caller to count as non-finite. Throws hinge::InputError when the file cannot be read.
std::vector<double> read_numbers(const std::string& path);

}  // namespace hinge::io
