// A public implementation's failure mode: normals from absolute coordinates, without subtracting a
// vertex first: N = x0 x x1 + x1 x x2 + x2 x x0 (the same vector as (x1 - x0) x (x2 - x0) in exact
// arithmetic). Far from the origin the terms are about |x|^2 and cancel to about |e|^2: the error grows
// with (|x| / |e|)^2 although nothing about the hinge's shape changed (theta is invariant under a
// translation, and so is its condition number). `hinge conform` must reject it on offsets.
#include "peer_formulas.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12],
                                                      double hess[144]) {
  using candidates::vertex;
  const auto x0 = vertex(x, 0), x1 = vertex(x, 1), x2 = vertex(x, 2), x3 = vertex(x, 3);
  const candidates::Normals m{x0.cross(x1) + x1.cross(x2) + x2.cross(x0), x3.cross(x2) + x2.cross(x1) + x1.cross(x3)};
  return candidates::peer(x, m, candidates::Angle::atan2, theta, grad, hess) ? 0 : 1;
}
