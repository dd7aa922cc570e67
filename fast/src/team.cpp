// The worker threads of an Assembler (team.hpp).
#include "team.hpp"

#include <chrono>

namespace hinge::fast::detail {

namespace {

inline void relax() {
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

// How long a waiting thread spins before it sleeps: the passes of one evaluation, and evaluations in a
// loop, follow each other within microseconds; a futex wake-up costs about as much as this spin.
constexpr auto kSpin = std::chrono::microseconds(50);

// Waits until a != old and returns its new value (acquire).
std::uint32_t await_change(const std::atomic<std::uint32_t>& a, std::uint32_t old) {
  const auto start = std::chrono::steady_clock::now();
  for (unsigned i = 1;; ++i) {
    const std::uint32_t v = a.load(std::memory_order_acquire);
    if (v != old) return v;
    relax();
    if (i % 64 == 0 && std::chrono::steady_clock::now() - start > kSpin) break;
  }
  for (;;) {
    a.wait(old, std::memory_order_acquire);
    const std::uint32_t v = a.load(std::memory_order_acquire);
    if (v != old) return v;
  }
}

// Waits until a == 0 (acquire).
void await_zero(const std::atomic<int>& a) {
  const auto start = std::chrono::steady_clock::now();
  for (unsigned i = 1;; ++i) {
    if (a.load(std::memory_order_acquire) == 0) return;
    relax();
    if (i % 64 == 0 && std::chrono::steady_clock::now() - start > kSpin) break;
  }
  for (;;) {
    const int v = a.load(std::memory_order_acquire);
    if (v == 0) return;
    a.wait(v, std::memory_order_acquire);
  }
}

}  // namespace

Team::~Team() {
  if (workers_.empty()) return;
  stop_ = true;
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  for (std::thread& w : workers_) w.join();
}

// The caller writes the job and then bumps the generation (release); a worker that sees the new
// generation (acquire) runs its part and counts itself off `pending_` (acq_rel); the caller, once that
// reaches 0 (acquire), sees every worker's writes. Every worker counts itself off, taking part or not,
// so no worker can still be reading job_ when the next region writes it.
void Team::dispatch(int threads, Job job, void* body) {
  while (workers_.size() < static_cast<std::size_t>(threads - 1)) {
    const int t = static_cast<int>(workers_.size()) + 1;
    workers_.emplace_back(&Team::work, this, t, generation_.load(std::memory_order_relaxed));
  }
  job_ = job;
  body_ = body;
  threads_ = threads;
  pending_.store(static_cast<int>(workers_.size()), std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  job(body, 0);
  await_zero(pending_);
}

void Team::work(int t, std::uint32_t seen) {
  for (;;) {
    seen = await_change(generation_, seen);
    if (stop_) return;
    if (t < threads_) job_(body_, t);
    if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_one();
  }
}

}  // namespace hinge::fast::detail
