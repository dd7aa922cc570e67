// Output files that appear whole or not at all (hinge/io/atomic_file.hpp).
#include "hinge/io/atomic_file.hpp"

#include <unistd.h>

#include <cerrno>

#include <stdexcept>
#include <system_error>

namespace hinge::io {

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  temporary_ = path_;
  temporary_ += ".tmp-" + std::to_string(::getpid());
  out_.open(temporary_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    const std::string why = std::error_code(errno, std::generic_category()).message();
    throw std::runtime_error("cannot write " + path_.string() + ": " + why);
  }
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

}  // namespace hinge::io
