// Wavefront OBJ reading and writing, exact to the bit (hinge/io/obj.hpp).
//
// Reading: `v x y z [w]` and `f a b c` (each of a, a/t, a//n, a/t/n; 1-based, or negative = relative to
// the last vertex read so far) matter, everything else is ignored. Coordinates go through std::from_chars,
// which rounds correctly; a leading '+' is accepted (from_chars does not take it). Non-finite or
// out-of-range coordinates, faces with other than three corners (no silent triangulation) and bad
// indices are errors "FILE:LINE: why". Writing: shortest round-trip (number.hpp), so every coordinate reads
// back bit for bit.
#include "hinge/io/obj.hpp"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <istream>
#include <limits>
#include <ostream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "hinge/core/errors.hpp"
#include "hinge/io/number.hpp"

namespace hinge::io {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// The whitespace-separated tokens of `line`, up to a '#' (a comment).
void tokenize(std::string_view line, std::vector<std::string_view>& tokens) {
  if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
  tokens.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    const std::size_t begin = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    if (i > begin) tokens.push_back(line.substr(begin, i - begin));
  }
}

// A lone leading '+' (not "+-" or "++"), which from_chars rejects, is dropped.
std::string_view drop_plus(std::string_view s) {
  if (s.size() > 1 && s[0] == '+' && s[1] != '+' && s[1] != '-') s.remove_prefix(1);
  return s;
}

class Parser {
 public:
  explicit Parser(std::string name) : name_(std::move(name)) {}

  void line(std::string_view text) {
    ++line_;
    tokenize(text, tokens_);
    if (tokens_.empty()) return;
    if (tokens_[0] == "v") {
      vertex(tokens_);
    } else if (tokens_[0] == "f") {
      face(tokens_);
    }
  }

  Mesh finish() {
    if (mesh_.faces.empty())  // docs/contract.md (version 2): a mesh with no faces is an error
      throw InputError(name_ + ": the mesh has no faces (" +
                       (mesh_.vertices.empty() ? std::string("the file has no v or f lines")
                                               : std::to_string(mesh_.vertices.size()) + " vertices, no f lines") +
                       ")");
    const std::size_t n = mesh_.vertices.size();
    for (std::size_t f = 0; f < mesh_.faces.size(); ++f) {
      for (const Index v : mesh_.faces[f]) {
        if (static_cast<std::size_t>(v) >= n) {
          fail_at(face_lines_[f], "vertex index " + std::to_string(v + 1) + " out of range (the file has " +
                                      std::to_string(n) + " vertices)");
        }
      }
    }
    return std::move(mesh_);
  }

  [[noreturn]] void fail(const std::string& why) const { fail_at(line_, why); }

  std::size_t line_number() const { return line_; }

 private:
  [[noreturn]] void fail_at(std::size_t line, const std::string& why) const {
    throw InputError(name_ + ":" + std::to_string(line) + ": " + why);
  }

  void vertex(const std::vector<std::string_view>& tokens) {
    if (tokens.size() < 4) {
      fail("vertex line with " + std::to_string(tokens.size() - 1) + " coordinates, need 3");
    }
    std::array<double, 3> x{};
    for (int c = 0; c < 3; ++c) x[c] = coordinate(tokens[c + 1]);
    // Further numbers (w, or the r g b colours some writers append) are checked for form and ignored.
    for (std::size_t k = 4; k < tokens.size(); ++k) {
      const auto s = drop_plus(tokens[k]);
      double ignored = 0.0;
      const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), ignored);
      if (ptr != s.data() + s.size() || (ec != std::errc{} && ec != std::errc::result_out_of_range)) {
        fail("malformed number '" + std::string(tokens[k]) + "' in vertex line");
      }
    }
    mesh_.vertices.push_back(x);
  }

  double coordinate(std::string_view token) const {
    const auto s = drop_plus(token);
    double x = 0.0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), x, std::chars_format::general);
    if (ec == std::errc::result_out_of_range) {
      fail("coordinate '" + std::string(token) + "' is outside the range of double (overflow, or underflow to zero)");
    }
    if (ec != std::errc{} || ptr != s.data() + s.size()) {
      fail("malformed coordinate '" + std::string(token) + "'");
    }
    if (!std::isfinite(x)) fail("non-finite coordinate '" + std::string(token) + "'");
    return x;
  }

  // An integer, optionally signed; false when `s` is not one or does not fit in 64 bits.
  static bool integer(std::string_view s, std::int64_t& value) {
    s = drop_plus(s);
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    return !s.empty() && ec == std::errc{} && ptr == s.data() + s.size();
  }

  void face(const std::vector<std::string_view>& tokens) {
    const std::size_t corners = tokens.size() - 1;
    if (corners != 3) {
      fail("face with " + std::to_string(corners) + " vertices; only triangles are accepted (no triangulation)");
    }
    std::array<Index, 3> f{};
    for (std::size_t k = 0; k < 3; ++k) {
      const std::string_view token = tokens[k + 1];
      // Forms a, a/t, a//n, a/t/n: only a is used; t and n must be integers where present.
      const std::size_t slash1 = token.find('/');
      const std::size_t slash2 = slash1 == std::string_view::npos ? slash1 : token.find('/', slash1 + 1);
      std::int64_t index = 0, ignored = 0;
      bool ok = integer(token.substr(0, slash1), index);
      if (ok && slash1 != std::string_view::npos) {
        const std::string_view t =
            token.substr(slash1 + 1, slash2 == std::string_view::npos ? slash2 : slash2 - slash1 - 1);
        if (slash2 == std::string_view::npos) {
          ok = integer(t, ignored);  // a/t
        } else {
          ok = (t.empty() || integer(t, ignored)) && integer(token.substr(slash2 + 1), ignored);  // a//n, a/t/n
        }
      }
      if (!ok) fail("malformed face vertex '" + std::string(token) + "' (expected a, a/t, a//n or a/t/n)");

      const auto n = static_cast<std::int64_t>(mesh_.vertices.size());
      if (index == 0) fail("vertex index 0 in face (OBJ indices start at 1)");
      if (index < 0) {
        if (n + index < 0) {
          fail("relative vertex index " + std::to_string(index) + " out of range (only " + std::to_string(n) +
               " vertices so far)");
        }
        index = n + index;
      } else {
        if (index > std::numeric_limits<Index>::max()) {
          fail("vertex index " + std::to_string(index) + " too large");
        }
        // Checked against the vertex count at the end of the file: forward references are allowed.
        index -= 1;
      }
      f[k] = static_cast<Index>(index);
    }
    mesh_.faces.push_back(f);
    face_lines_.push_back(line_);
  }

  std::string name_;
  std::size_t line_ = 0;
  Mesh mesh_;
  std::vector<std::size_t> face_lines_;
  std::vector<std::string_view> tokens_;  // of the current line
};

}  // namespace

Mesh read_obj(std::istream& in, const std::string& name_for_errors) {
  Parser parser(name_for_errors);
  std::string text;
  while (std::getline(in, text)) parser.line(text);
  if (in.bad()) {
    throw InputError(name_for_errors + ":" + std::to_string(parser.line_number() + 1) + ": read error");
  }
  return parser.finish();
}

Mesh read_obj(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int error = errno;
    throw InputError(path + ":0: cannot open for reading" +
                     (error != 0 ? std::string(": ") + std::strerror(error) : ""));
  }
  return read_obj(in, path);
}

void write_obj(std::ostream& out, const Mesh& mesh, const std::string& comment) {
  std::string buffer;
  buffer.reserve(1 << 16);
  auto flush_if_full = [&] {
    if (buffer.size() >= (1 << 16) - 128) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  };
  if (!comment.empty()) buffer += "# " + comment + "\n";
  for (const auto& v : mesh.vertices) {
    buffer += 'v';
    for (const double c : v) {
      buffer += ' ';
      append_double(buffer, c);
    }
    buffer += '\n';
    flush_if_full();
  }
  for (const auto& f : mesh.faces) {
    buffer += 'f';
    for (const Index v : f) {
      buffer += ' ';
      buffer += std::to_string(static_cast<std::int64_t>(v) + 1);
    }
    buffer += '\n';
    flush_if_full();
  }
  out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
}

}  // namespace hinge::io
