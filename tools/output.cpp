// Exact number formatting and atomic output files (tools/output.hpp).
#include "output.hpp"

#include <charconv>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace hinge::tools {

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

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  temporary_ = path_;
  temporary_ += ".tmp-" + std::to_string(::getpid());
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot write " + temporary_.string());
  out_.exceptions(std::ios::badbit);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::error_code ignored;
    std::filesystem::remove(temporary_, ignored);
  }
}

void AtomicFile::commit() {
  out_.flush();
  out_.close();
  if (out_.fail()) throw std::runtime_error("writing " + path_.string() + " failed");
  std::filesystem::rename(temporary_, path_);
  committed_ = true;
}

}  // namespace hinge::tools
