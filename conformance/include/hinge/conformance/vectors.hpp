// hinge/conformance/vectors.hpp: the committed conformance vectors (conformance/hinges, hinges-float32, deep,
// deep-float32, meshes; docs/conformance-format.md), regenerated bit for bit by `hinge conform --write-vectors`.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>

namespace hinge::conformance {

// The format version of the committed files (docs/conformance-format.md).
inline constexpr int format_version = 2;

// What write_vectors wrote: hinge cases per set, and the deep sets' drops (a draw of hard_cases that is not
// a valid hinge, or whose outputs leave the format's range, is `invalid`; one the oracle cannot certify
// within its precision cap is `uncertified`).
struct VectorsSummary {
  std::size_t quick = 0, float32 = 0, deep = 0, deep_float32 = 0, meshes = 0;
  std::size_t energy_cases = 0;  // lines of energies/<energy>.jsonl, all energies
  std::size_t deep_draws = 0, deep_invalid = 0, deep_uncertified = 0;
  std::size_t deep_float32_draws = 0, deep_float32_invalid = 0, deep_float32_uncertified = 0;
};

// Regenerates the committed vectors (conformance/: docs/conformance-format.md) under `dir`, bit for bit:
// hinges/<category>.jsonl, hinges-float32/<category>.jsonl, deep/<family>.jsonl, deep-float32/<family>.jsonl,
// energies/<energy>.jsonl (the energy cases' conditioning), meshes/*.obj, *.mtx, *.gradient.txt and
// meshes/meshes.jsonl. `progress(done, total)` is called after each
// hinge case. Throws std::logic_error if a quick-set or mesh vector cannot be certified.
VectorsSummary write_vectors(const std::filesystem::path& dir,
                             const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace hinge::conformance
