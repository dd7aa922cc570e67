// Progress lines on standard error (tools/progress.hpp).
#include "progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace hinge::tools {

Progress::Progress(std::string what, std::size_t total, bool force)
    : what_(std::move(what)), total_(total), enabled_(force || ::isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

void Progress::update(std::size_t done) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::seconds(1)) return;
  last_ = now;
  shown_ = true;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  if (total_)
    std::fprintf(stderr, "\r%s: %zu of %zu (%.0f%%), %.0f s", what_.c_str(), done, total_,
                 100.0 * static_cast<double>(done) / static_cast<double>(total_), seconds);
  else std::fprintf(stderr, "\r%s: %zu, %.0f s", what_.c_str(), done, seconds);
  std::fflush(stderr);
}

Progress::~Progress() {
  if (shown_) std::fprintf(stderr, "\n");
}

}  // namespace hinge::tools
