// hinge/conformance/inputs.hpp: the conformance inputs (docs/conformance.md): about 300 hinges in nine
// categories, the hard families of docs/hard-cases.md, and the meshes with boundaries. Deterministic: built
// with IEEE-754 basic operations (the project compiles without contraction into fused multiply-adds) and
// correctly rounded MPFR functions, so the same bits come out on every platform and the committed vectors
// can be checked by regenerating them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hinge/core/mesh.hpp"

namespace hinge::conformance {

// One hinge of the conformance set: "category/NN-tag"; for the conformance of bending energies also its
// rest hinge (energy_inputs.hpp).
struct Case {
  std::string id, category;
  std::array<double, 12> x{};
  std::optional<std::array<double, 12>> rest;
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

// The deep set's hinges (docs/conformance-format.md, "deep/"): hard_cases(deep_seed, deep_per_family), each
// with the id "<family>/deep-NNNN-<tag>" (NNNN its index in its family) and its family as category.
inline constexpr std::uint64_t deep_seed = 0x5eedde3d;
inline constexpr int deep_per_family = 130;
std::vector<Case> deep_inputs();

// float32: every coordinate zero or a normal float (held in the double), every output certified in
// binary32 (oracle.hpp, Options::binary32) zero or a normal float.
// - float32_inputs(): the nine categories of inputs(), about as many hinges each, built within float32's
//   range (scales 2^-50 to 2^50, offsets to 2^20, angles to 1e-30 from flat and from folded, caps to
//   1e-12, spikes to 1e12, hinge edges to 2^-60 of the others);
// - hard_cases_float32(): the eight families of hard_cases within those ranges (combined: needles to 1e-4,
//   offset to 1e3 with the cap at least 1e-5 of it, scaled 2^-40 to 2^40), invalid draws dropped, ids
//   "family/N-tag";
// - deep_float32_inputs(): the deep float32 set's hinges, hard_cases_float32(deep_seed, deep_per_family)
//   identified as deep_inputs() identifies its own.
std::vector<Case> float32_inputs();
std::vector<Case> hard_cases_float32(std::uint64_t seed, int per_family);
std::vector<Case> deep_float32_inputs();

// The meshes (with boundaries) whose hinges form the category boundary-meshes, and whose energies,
// gradients and Hessians are conformance vectors of their own.
struct MeshCase {
  std::string name;
  Mesh deformed, rest;
};
std::vector<MeshCase> meshes();

}  // namespace hinge::conformance
