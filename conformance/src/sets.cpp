// The committed conformance sets (hinge/conformance/sets.hpp), read from the copies compiled into the library
// (conformance/CMakeLists.txt embeds every hinges/, hinges-float32/, deep/ and deep-float32/ file): each file's
// lines parsed once, by a reader of exactly the format write_vectors writes (docs/conformance-format.md),
// numbers by std::from_chars (correctly rounded, locale-free).
#include "hinge/conformance/sets.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <stdexcept>
#include <string_view>

namespace hinge::conformance {
namespace {

// The embedded files: {name ("hinges/needles.jsonl"), first byte, one past the last}, ended by zeros
// (generated: build/.../conformance/embedded_sets.cpp).
struct EmbeddedFile {
  const char* name;
  const char* begin;
  const char* end;
};
extern "C" const EmbeddedFile hinge_conformance_embedded[];

// One line of a hinge set: `{"id": "...", "category": "...", "x": [12], "theta": t, "grad": [12], "hess": [144],
// "length": l, "scale": [3], "kappa": [3], "bits": b}`, the keys in that order.
class LineReader {
 public:
  LineReader(std::string_view line, const std::string& where)
      : p_(line.data()), end_(p_ + line.size()), where_(where) {}

  Expected read() {
    Expected e;
    expect("{");
    e.input.id = key_string("id");
    e.input.category = key_string("category");
    key_numbers("x", e.input.x.data(), 12);
    key_numbers("theta", &e.values.theta, 1);
    key_numbers("grad", e.values.grad.data(), 12);
    key_numbers("hess", e.values.hess.data(), 144);
    key_numbers("length", &e.conditioning.length, 1);
    key_numbers("scale", e.conditioning.scale.data(), 3);
    key_numbers("kappa", e.conditioning.kappa.data(), 3);
    key("bits");
    skip_spaces();
    const auto [q, error] = std::from_chars(p_, end_, e.values.bits);
    if (error != std::errc()) fail("an integer");
    p_ = q;
    expect("}");
    skip_spaces();
    if (p_ != end_) fail("the end of the line");
    e.values.path = oracle::Path::interval;
    return e;
  }

 private:
  [[noreturn]] void fail(const char* wanted) const {
    throw std::logic_error("conformance set " + where_ + ": expected " + wanted + " at '" +
                           std::string(p_, std::min<std::size_t>(20, static_cast<std::size_t>(end_ - p_))) + "'");
  }
  void skip_spaces() {
    while (p_ != end_ && *p_ == ' ') ++p_;
  }
  void expect(std::string_view token) {
    skip_spaces();
    if (static_cast<std::size_t>(end_ - p_) < token.size() || std::memcmp(p_, token.data(), token.size()) != 0)
      fail(token.data());
    p_ += token.size();
  }
  void key(const char* name) {
    if (!first_key_) expect(",");
    first_key_ = false;
    expect("\"");
    expect(name);
    expect("\"");
    expect(":");
  }
  // A string without escapes (ids and categories are written without them).
  std::string key_string(const char* name) {
    key(name);
    expect("\"");
    const char* start = p_;
    while (p_ != end_ && *p_ != '"') {
      if (*p_ == '\\') fail("a string without escapes");
      ++p_;
    }
    std::string s(start, p_);
    expect("\"");
    return s;
  }
  double number() {
    skip_spaces();
    double v = 0;
    const auto [q, error] = std::from_chars(p_, end_, v);
    if (error != std::errc()) fail("a number");
    p_ = q;
    return v;
  }
  // One number, or an array of n.
  void key_numbers(const char* name, double* out, std::size_t n) {
    key(name);
    if (n == 1) {
      *out = number();
      return;
    }
    expect("[");
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0) expect(",");
      out[i] = number();
    }
    expect("]");
  }

  const char* p_;
  const char* end_;
  std::string where_;
  bool first_key_ = true;
};

// Appends the lines of the embedded file `name` (none if there is no such file), checking each one's category.
void read_file(const std::string& name, const std::string& category, std::vector<Expected>& out) {
  const std::string_view text = embedded_file(name);
  std::size_t start = 0, line_number = 1;
  while (start < text.size()) {
    std::size_t stop = text.find('\n', start);
    if (stop == std::string_view::npos) stop = text.size();
    if (stop > start) {
      out.push_back(LineReader(text.substr(start, stop - start), name + ":" + std::to_string(line_number)).read());
      if (out.back().input.category != category)
        throw std::logic_error("conformance set " + name + ": a case of category " + out.back().input.category);
    }
    start = stop + 1;
    ++line_number;
  }
}

std::vector<Expected> load(Dtype dtype, Depth depth) {
  const bool f32 = dtype == Dtype::float32;
  const std::string quick_dir = f32 ? "hinges-float32/" : "hinges/", deep_dir = f32 ? "deep-float32/" : "deep/";
  std::vector<Expected> out;
  const std::vector<std::string>& quick = categories();
  for (const std::string& category : set_categories(dtype, depth)) {
    if (std::find(quick.begin(), quick.end(), category) != quick.end())
      read_file(quick_dir + category + ".jsonl", category, out);
    if (depth == Depth::deep) read_file(deep_dir + category + ".jsonl", category, out);
  }
  if (out.empty()) throw std::logic_error("conformance set: nothing embedded for " + std::string(dtype_name(dtype)));
  return out;
}

}  // namespace

// An embedded file's text; empty when there is none (a deep category a set does not have).
std::string_view embedded_file(const std::string& name) {
  for (const EmbeddedFile* f = hinge_conformance_embedded; f->name != nullptr; ++f)
    if (name == f->name) return {f->begin, static_cast<std::size_t>(f->end - f->begin)};
  return {};
}

const char* depth_name(Depth d) { return d == Depth::deep ? "deep" : "quick"; }

Depth parse_depth(const std::string& name) {
  if (name == "quick") return Depth::quick;
  if (name == "deep") return Depth::deep;
  throw std::invalid_argument("unknown depth '" + name + "' (expected quick or deep)");
}

const std::vector<Expected>& conformance_set(Dtype dtype, Depth depth) {
  // Each set parsed on first use, once (thread-safe initialization of function-local statics).
  if (dtype == Dtype::float64) {
    if (depth == Depth::quick) {
      static const std::vector<Expected> set = load(Dtype::float64, Depth::quick);
      return set;
    }
    static const std::vector<Expected> set = load(Dtype::float64, Depth::deep);
    return set;
  }
  if (depth == Depth::quick) {
    static const std::vector<Expected> set = load(Dtype::float32, Depth::quick);
    return set;
  }
  static const std::vector<Expected> set = load(Dtype::float32, Depth::deep);
  return set;
}

std::vector<std::string> set_categories(Dtype, Depth depth) {
  std::vector<std::string> names = categories();
  if (depth == Depth::deep)
    for (const std::string& family : hard_families())
      if (std::find(names.begin(), names.end(), family) == names.end()) names.push_back(family);
  return names;
}

}  // namespace hinge::conformance
