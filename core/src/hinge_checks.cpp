// The contract's validity checks and error names (hinge/core/hinge_checks.hpp).
#include "hinge/core/hinge_checks.hpp"

#include <cmath>

#include "hinge/core/predicates.hpp"

namespace hinge {

const char* coordinate_name(int i) {
  static const char* const names[12] = {"x0.x", "x0.y", "x0.z", "x1.x", "x1.y", "x1.z",
                                        "x2.x", "x2.y", "x2.z", "x3.x", "x3.y", "x3.z"};
  return names[i];
}

void check_finite(const std::array<double, 12>& x) {
  for (int i = 0; i < 12; ++i)
    if (!std::isfinite(x[i])) throw InputError(std::string("coordinate ") + coordinate_name(i) + " is not finite");
}

void throw_zero_hinge_edge() { throw InputError("degenerate hinge: the hinge edge has zero length (x1 == x2)"); }

void throw_zero_area(bool upper) {
  throw InputError(upper ? "degenerate hinge: the upper triangle (x0, x1, x2) has zero area"
                         : "degenerate hinge: the lower triangle (x3, x2, x1) has zero area");
}

void check_areas(const std::array<double, 12>& x) {
  const Point x0{x[0], x[1], x[2]}, x1{x[3], x[4], x[5]}, x2{x[6], x[7], x[8]}, x3{x[9], x[10], x[11]};
  if (zero_area_exact(x0, x1, x2)) throw_zero_area(true);
  if (zero_area_exact(x3, x2, x1)) throw_zero_area(false);
}

void check_hinge(const std::array<double, 12>& x) {
  check_finite(x);
  if (x[3] == x[6] && x[4] == x[7] && x[5] == x[8]) throw_zero_hinge_edge();
  check_areas(x);
}

std::string describe_hinge(const Topology& topology, Index hinge) {
  const Hinge& h = topology.hinges[hinge];
  const auto s = [](auto v) { return std::to_string(v); };
  return "hinge " + s(hinge) + " (edge " + s(h.x[1]) + "-" + s(h.x[2]) + ", faces " + s(h.upper) + " and " +
         s(h.lower) + "; OBJ numbering: vertices " + s(h.x[1] + 1) + "-" + s(h.x[2] + 1) + ", faces " + s(h.upper + 1) +
         " and " + s(h.lower + 1) + "): ";
}

void throw_mesh_mismatch(const char* what) {
  throw InputError(std::string("the ") + what +
                   " mesh must have the same vertices (count) and faces as the deformed mesh");
}

void check_same_mesh(const Mesh& mesh, const Topology& topology, const char* what) {
  if (mesh.vertices.size() != topology.vertex_count || mesh.faces != topology.faces) throw_mesh_mismatch(what);
}

}  // namespace hinge
