// hinge/io/atomic_file.hpp: output files that appear whole or not at all (docs/contract.md: no output file
// is left behind by a failed command).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

namespace hinge::io {

// An output file written under a temporary name and renamed over `path` by commit(); destroyed without
// commit() (an error on the way), it removes the temporary: no partial file is ever left behind.
class AtomicFile {
 public:
  explicit AtomicFile(const std::string& path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  std::ostream& stream() { return out_; }
  void commit();  // throws std::runtime_error if writing failed

 private:
  std::filesystem::path path_, temporary_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace hinge::io
