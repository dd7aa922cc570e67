// The non-template parts of Algorithm 2's assembly (hinge/fast/assemble.hpp).
#include <algorithm>
#include <bit>
#include <chrono>
#include <limits>
#include <numeric>
#include <string>

#include "hinge/fast/assemble.hpp"

namespace hinge::fast::detail {

std::string describe_hinge(const Topology& topology, Index hinge) {
  const Hinge& h = topology.hinges[hinge];
  const auto s = [](auto v) { return std::to_string(v); };
  return "hinge " + s(hinge) + " (edge " + s(h.x[1]) + "-" + s(h.x[2]) + ", faces " + s(h.upper) + " and " + s(h.lower) +
         "; OBJ numbering: vertices " + s(h.x[1] + 1) + "-" + s(h.x[2] + 1) + ", faces " + s(h.upper + 1) + " and " +
         s(h.lower + 1) + "): ";
}

// ---- Team ----------------------------------------------------------------------------------------------

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

// ---- the assembly's ranges -----------------------------------------------------------------------------

AssemblyPlan plan_assembly(const Pattern& pattern, int parts) {
  const auto& faces = pattern.faces();
  const std::size_t n = pattern.vertex_count();
  const std::size_t P = static_cast<std::size_t>(std::max(parts, 1));
  AssemblyPlan plan;
  plan.parts = static_cast<int>(P);
  plan.vertex.assign(P + 1, static_cast<Index>(n));
  plan.vertex[0] = 0;
  plan.face_begin.assign(P, 0);
  plan.face_end.assign(P, 0);
  if (P == 1) {
    plan.face_end[0] = faces.size();
    return plan;
  }
  // low[x]: the cost of the faces whose lowest vertex is below x; high[x]: of those whose highest is. The
  // faces range [a, b) visits are those with lowest < b and highest >= a: cost low[b] - high[a].
  std::vector<std::int64_t> low(n + 1, 0), high(n + 1, 0);
  for (const Pattern::Face& F : faces) {
    if (F.highest < 0) continue;
    const std::int64_t c = kFaceCost + kOwnedHingeCost * std::popcount(F.owns);
    low[static_cast<std::size_t>(F.lowest) + 1] += c;
    high[static_cast<std::size_t>(F.highest) + 1] += c;
  }
  std::partial_sum(low.begin(), low.end(), low.begin());
  std::partial_sum(high.begin(), high.end(), high.begin());
  // Greedy cover of [0, n) by ranges of cost at most M, each as long as it can be: the number of ranges
  // (P + 1 when more than P are needed), their ends into `ends` when given. Minimal for that M.
  auto cover = [&](std::int64_t M, std::vector<Index>* ends) {
    std::size_t a = 0, used = 0;
    while (a < n) {
      if (used == P) return P + 1;
      const auto it = std::upper_bound(low.begin() + static_cast<std::ptrdiff_t>(a) + 1, low.end(), high[a] + M);
      const std::size_t b = static_cast<std::size_t>(it - low.begin()) - 1;
      if (b <= a) return P + 1;  // the faces of vertex a alone cost more than M
      if (ends) (*ends)[used + 1] = static_cast<Index>(b);
      ++used;
      a = b;
    }
    return used;
  };
  std::int64_t lo = 0, hi = low[n];  // one range covering everything costs low[n]
  while (lo < hi) {
    const std::int64_t mid = lo + (hi - lo) / 2;
    if (cover(mid, nullptr) <= P) hi = mid;
    else lo = mid + 1;
  }
  cover(lo, &plan.vertex);
  // The interval of faces each nonempty range touches.
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  std::fill(plan.face_begin.begin(), plan.face_begin.end(), none);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Pattern::Face& F = faces[f];
    if (F.highest < 0) continue;
    std::size_t t = static_cast<std::size_t>(std::upper_bound(plan.vertex.begin(), plan.vertex.end(), F.lowest) - plan.vertex.begin()) - 1;
    for (; t < P && plan.vertex[t] <= F.highest; ++t) {
      if (plan.vertex[t] == plan.vertex[t + 1]) continue;
      if (plan.face_begin[t] == none) plan.face_begin[t] = f;
      plan.face_end[t] = f + 1;
    }
  }
  for (std::size_t t = 0; t < P; ++t)
    if (plan.face_begin[t] == none) plan.face_begin[t] = plan.face_end[t] = 0;
  return plan;
}

}  // namespace hinge::fast::detail
