// hinge/core/hinge_checks.hpp: what makes a hinge invalid, decided exactly on its 12 input doubles
// (docs/contract.md: a non-finite coordinate, a hinge edge of zero length, a triangle of exactly zero area),
// and how errors name a coordinate and a mesh's hinge. Every evaluator (reference, fast, oracle, the
// command) reports these conditions with the messages below, so that they read the same everywhere.
//
//                 x0
//               /  \          upper triangle (x0, x1, x2), hinge edge x1 -> x2
//             x1 -- x2        lower triangle (x3, x2, x1)
//               \  /
//                x3           variables: x0.x, x0.y, x0.z, x1.x, ..., x3.z (12)
#pragma once

#include <array>
#include <string>

#include "hinge/core/errors.hpp"
#include "hinge/core/mesh.hpp"

namespace hinge {

// "x0.x", "x0.y", ..., "x3.z": the name of coordinate i (0 <= i < 12).
const char* coordinate_name(int i);

// The checks in their order (the first failing one is reported), each throwing hinge::InputError:
//   "coordinate x1.y is not finite"
//   "degenerate hinge: the hinge edge has zero length (x1 == x2)"
//   "degenerate hinge: the upper triangle (x0, x1, x2) has zero area"
//   "degenerate hinge: the lower triangle (x3, x2, x1) has zero area"
void check_hinge(const std::array<double, 12>& x);
// The same checks one at a time, for kernels that decide the common case with a filter first.
void check_finite(const std::array<double, 12>& x);  // names the first non-finite coordinate
[[noreturn]] void throw_zero_hinge_edge();
[[noreturn]] void throw_zero_area(bool upper);
// The exact area checks of both triangles (zero_area_exact), for a hinge already known finite with x1 != x2.
void check_areas(const std::array<double, 12>& x);

// "hinge 7 (edge 3-9, faces 2 and 5; OBJ numbering: vertices 4-10, faces 3 and 6): ", the prefix of every
// error about hinge `h` of `topology`.
std::string describe_hinge(const Topology& topology, Index h);

// Runs f(); rethrows hinge::InputError / hinge::DomainError with hinge `h` named in front of the message.
template <class F>
auto for_hinge(const Topology& topology, Index h, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    throw InputError(describe_hinge(topology, h) + e.what());
  } catch (const DomainError& e) {
    throw DomainError(describe_hinge(topology, h) + e.what());
  }
}

// Throws InputError "the <what> mesh must have the same vertices (count) and faces as the deformed mesh"
// unless `mesh` has the vertex count and the faces of `topology` (what: "rest", "previous", "deformed").
void check_same_mesh(const Mesh& mesh, const Topology& topology, const char* what);
[[noreturn]] void throw_mesh_mismatch(const char* what);

}  // namespace hinge
