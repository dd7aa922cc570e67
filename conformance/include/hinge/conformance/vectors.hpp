// hinge/conformance/vectors.hpp: the committed conformance vectors (conformance/hinges, conformance/meshes;
// docs/conformance-format.md), regenerated bit for bit by `hinge conform --write-vectors`.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>

namespace hinge::conformance {

// The format version of the committed files (docs/conformance-format.md).
inline constexpr int format_version = 1;

// Regenerates the committed vectors (conformance/: docs/conformance-format.md) under `dir`, bit for bit:
// hinges/<category>.jsonl, meshes/*.obj, *.mtx, *.gradient.txt and meshes/meshes.jsonl. `progress(done,
// total)` is called after each hinge case. Throws std::logic_error if a vector cannot be certified.
void write_vectors(const std::filesystem::path& dir,
                   const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace hinge::conformance
