// tools/output.hpp: numbers that read back exactly, and output files that appear whole or not at all.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace hinge::tools {

// Shortest decimal that reads back to exactly `x` (std::to_chars), with ".0" on integral values so
// that every number looks like a double ("1.0", "-0.0", "1e+300", "5e-324").
std::string format_double(double x);
void append_double(std::string& out, double x);

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

}  // namespace hinge::tools
