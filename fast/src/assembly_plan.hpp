// fast/src/assembly_plan.hpp: how the assembly pass of Algorithm 2 is split between threads: ranges of
// column vertices whose estimated work balances (assembler_impl.hpp explains why any split gives the same
// bits).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "hinge/fast/pattern.hpp"

namespace hinge::fast::detail {

// The assembly pass's split of the column vertices for `parts` threads: range t is vertices
// [vertex[t], vertex[t+1]), whose faces all lie in [face_begin[t], face_end[t]) (empty: begin == end).
struct AssemblyPlan {
  int parts = 0;
  std::vector<Index> vertex;
  std::vector<std::size_t> face_begin, face_end;
};

// The assembly pass's split into `parts` column-vertex ranges (parts >= 1) that balance the estimated
// work: each face costs every range it writes into kFaceCost plus kOwnedHingeCost per hinge it owns
// (its geometry, eq. (7) and its owned edges' terms are computed in full by every such range). The ranges
// minimise the largest cost; some may be empty. Linear in the mesh (computed once per thread count).
constexpr std::int64_t kFaceCost = 2, kOwnedHingeCost = 3;
AssemblyPlan plan_assembly(const Pattern& pattern, int parts);
// The assembly uses at most 1 + faces / kFacesPerPart threads (a range of about a thousand faces takes
// some 100 microseconds; starting a region of the team takes microseconds).
constexpr std::size_t kFacesPerPart = 1024;

}  // namespace hinge::fast::detail
