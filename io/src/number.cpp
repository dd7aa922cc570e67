// Numbers that read back exactly (hinge/io/number.hpp).
#include "hinge/io/number.hpp"

#include <charconv>
#include <fstream>
#include <limits>
#include <ostream>
#include <string_view>

#include "hinge/core/errors.hpp"

namespace hinge::io {

void append_double(std::string& out, double x) {
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  std::string_view s(buffer, static_cast<std::size_t>(end - buffer));
  out += s;
  if (s.find_first_of(".einn") == std::string_view::npos) out += ".0";  // "inf"/"nan" never reach here
}

std::string format_double(double x) {
  std::string s;
  append_double(s, x);
  return s;
}

void append_array(std::string& out, const double* values, std::size_t count) {
  out += '[';
  for (std::size_t i = 0; i < count; ++i) {
    if (i) out += ", ";
    append_double(out, values[i]);
  }
  out += ']';
}

void write_numbers(std::ostream& out, const std::vector<double>& values) {
  std::string line;
  for (double v : values) {
    line.clear();
    append_double(line, v);
    line += '\n';
    out << line;
  }
}

std::vector<double> read_numbers(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read " + path);
  std::vector<double> values;
  for (std::string t; in >> t;) {
    double v = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    values.push_back(ec == std::errc() && end == t.data() + t.size() ? v : std::numeric_limits<double>::quiet_NaN());
  }
  if (in.bad()) throw InputError("reading " + path + " failed");
  return values;
}

}  // namespace hinge::io
