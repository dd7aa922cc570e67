// The assembly's split between threads (assembly_plan.hpp).
#include "assembly_plan.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <numeric>

namespace hinge::fast::detail {

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
    std::size_t t = static_cast<std::size_t>(std::upper_bound(plan.vertex.begin(), plan.vertex.end(), F.lowest) -
                                             plan.vertex.begin()) -
                    1;
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
