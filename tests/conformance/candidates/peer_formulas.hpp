// tests/conformance/candidates/peer_formulas.hpp: theta and its gradient as public implementations write
// them, from normals given by the caller: theta = atan2((n x n~) . e0^, n . n~) (or acos), the gradient
// by eq. (4) with altitudes |N| / l and cosines of the triangles' angles. Each peer_* candidate feeds it
// the normals (or the angle formula) of one failure mode; the Hessian is the reference's, so that only
// that failure shows.
#pragma once

#include <Eigen/Dense>
#include <cmath>

#include "reference_double.hpp"

namespace candidates {

using V = Eigen::Vector3d;

inline V vertex(const double x[12], int i) { return V(x[3 * i], x[3 * i + 1], x[3 * i + 2]); }

// N and Nt: (twice the area) normals of the upper triangle (x0, x1, x2) and the lower (x3, x2, x1).
struct Normals {
  V N, Nt;
};

enum class Angle { atan2, acos };

// theta and grad theta (eq. (4)) from the normals `m`; the Hessian from the reference. False when the
// reference cannot evaluate the hinge.
inline bool peer(const double x[12], const Normals& m, Angle angle, double* theta, double grad[12], double hess[144]) {
  if (!reference_double(x, theta, grad, hess)) return false;
  const V x0 = vertex(x, 0), x1 = vertex(x, 1), x2 = vertex(x, 2), x3 = vertex(x, 3);
  const V e0 = x2 - x1;
  const V n = m.N.normalized(), nt = m.Nt.normalized();
  const double c = n.dot(nt), s = n.cross(nt).dot(e0.normalized());
  *theta = angle == Angle::atan2 ? std::atan2(s, c) : std::copysign(std::acos(std::fmax(-1.0, std::fmin(1.0, c))), s);
  auto cosine = [](const V& a, const V& b) { return a.dot(b) / (a.norm() * b.norm()); };
  auto altitude = [](const V& N, const V& edge) { return N.norm() / edge.norm(); };  // 2A / l
  const V g0 = -n / altitude(m.N, e0);
  const V g3 = -nt / altitude(m.Nt, e0);
  const V g1 =
      cosine(x0 - x2, x1 - x2) / altitude(m.N, x0 - x2) * n + cosine(x3 - x2, x1 - x2) / altitude(m.Nt, x3 - x2) * nt;
  const V g2 =
      cosine(x0 - x1, x2 - x1) / altitude(m.N, x1 - x0) * n + cosine(x3 - x1, x2 - x1) / altitude(m.Nt, x1 - x3) * nt;
  const V g[4] = {g0, g1, g2, g3};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 3; ++k) grad[3 * i + k] = g[i][k];
  return true;
}

// The normals with the hinge edge as one factor (what the reference does: docs/conformance.md).
inline Normals hinge_edge_normals(const double x[12]) {
  const V x0 = vertex(x, 0), x1 = vertex(x, 1), x2 = vertex(x, 2), x3 = vertex(x, 3);
  return {(x1 - x0).cross(x2 - x1), (x2 - x1).cross(x1 - x3)};
}

}  // namespace candidates
