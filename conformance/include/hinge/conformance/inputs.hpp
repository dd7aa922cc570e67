// hinge/conformance/inputs.hpp: the conformance inputs (docs/conformance.md): about 300 hinges in nine
// categories, the hard families of docs/hard-cases.md, and the meshes with boundaries. Deterministic: built
// with IEEE-754 basic operations (the project compiles without contraction into fused multiply-adds) and
// correctly rounded MPFR functions, so the same bits come out on every platform and the committed vectors
// can be checked by regenerating them.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hinge/core/mesh.hpp"

namespace hinge::conformance {

// One hinge of the conformance set: "category/NN-tag".
struct Case {
  std::string id, category;
  std::array<double, 12> x{};
};

// The categories, in report order: well-shaped, rotations, scales, offsets, near-flat, near-folded,
// needles, short-hinge-edges, boundary-meshes.
const std::vector<std::string>& categories();

// The conformance inputs (about 300 hinges), category by category.
std::vector<Case> inputs();

// The hard families (docs/hard-cases.md, ctest label hard): needles (caps and spikes to 1e-15),
// short-hinge-edges (2^-1 to 2^-60 of the other edges), near-flat (|theta| to 1e-15), near-folded (to pi -
// 1e-15), folded (exactly folded or flat, lattice planes, scaled and offset), offsets (to 1e16), scales
// (2^-500 to 2^500), combined (needles offset and scaled): `per_family` random draws of each from
// `seed` (SplitMix64, the same doubles on every platform), invalid draws dropped. Ids "family/N-tag".
const std::vector<std::string>& hard_families();
std::vector<Case> hard_cases(std::uint64_t seed, int per_family);

// The meshes (with boundaries) whose hinges form the category boundary-meshes, and whose energies,
// gradients and Hessians are conformance vectors of their own.
struct MeshCase {
  std::string name;
  Mesh deformed, rest;
};
std::vector<MeshCase> meshes();

}  // namespace hinge::conformance
