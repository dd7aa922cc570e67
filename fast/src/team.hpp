// fast/src/team.hpp: the worker threads of an Assembler (hinge/fast/assemble.hpp), kept for all its
// evaluations, and the split of a pass into fixed chunks that the threads take in any order.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
#include <type_traits>
#include <vector>

namespace hinge::fast::detail {

// A team of worker threads that stays for many parallel regions: run(threads, body) calls body(t) for
// t = 0 .. threads - 1, t = 0 on the caller's thread, the others on workers (created on first need and
// kept), and returns when all have returned. Between regions a worker spins briefly (the next pass or
// evaluation usually follows at once) and then sleeps on a futex (std::atomic::wait). One region at a
// time: not for concurrent use. A body must not throw (it would terminate the program). A copy or a
// moved-to team starts without workers (the threads belong to the original).
class Team {
 public:
  Team() = default;
  Team(const Team&) {}
  Team& operator=(const Team&) { return *this; }
  ~Team();

  template <class F>
  void run(int threads, F&& body) {
    if (threads <= 1) {
      body(0);
      return;
    }
    using Body = std::remove_reference_t<F>;
    dispatch(
        threads, [](void* b, int t) noexcept { (*static_cast<Body*>(b))(t); },
        const_cast<void*>(static_cast<const void*>(std::addressof(body))));
  }
  int workers() const { return static_cast<int>(workers_.size()); }

 private:
  using Job = void (*)(void*, int) noexcept;
  void dispatch(int threads, Job job, void* body);
  void work(int t, std::uint32_t seen);

  alignas(64) std::atomic<std::uint32_t> generation_{0};  // bumped by the caller to start a region
  alignas(64) std::atomic<int> pending_{0};               // workers that have not finished the region
  Job job_ = nullptr;
  void* body_ = nullptr;
  int threads_ = 0;
  bool stop_ = false;
  std::vector<std::thread> workers_;
};

// body(begin, end, chunk) over fixed chunks of [0, count), taken in turn by up to `threads` threads of
// `team` (no more threads than chunks).
template <class F>
void for_chunks(Team& team, std::size_t count, std::size_t chunk, int threads, F&& body) {
  const std::size_t chunks = (count + chunk - 1) / chunk;
  std::atomic<std::size_t> next{0};
  team.run(static_cast<int>(
               std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), std::max<std::size_t>(chunks, 1))),
           [&](int) {
             for (std::size_t c; (c = next.fetch_add(1, std::memory_order_relaxed)) < chunks;)
               body(c * chunk, std::min(count, (c + 1) * chunk), c);
           });
}

}  // namespace hinge::fast::detail
