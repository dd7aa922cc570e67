// tools/progress.hpp: a progress line on standard error for long runs (shown only when standard error
// is a terminal, or when forced), at most once a second, cleared at the end.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace hinge::tools {

class Progress {
 public:
  Progress(std::string what, std::size_t total, bool force = false);
  ~Progress();
  void update(std::size_t done);

 private:
  std::string what_;
  std::size_t total_;
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace hinge::tools
