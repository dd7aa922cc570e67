// A public implementation's failure mode: the normals from the two long edges of each triangle,
// N = (x1 - x0) x (x2 - x0) and Nt = (x2 - x3) x (x1 - x3). On a short hinge edge these are nearly
// parallel, the cross products lose log2(L / |e0|) bits, and the normals are no longer perpendicular to
// e0: theta and its gradient err by about u L / |e0| where their condition numbers stay moderate.
// `hinge conform` must reject it on short-hinge-edges.
#include "peer_formulas.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12],
                                                      double hess[144]) {
  using candidates::vertex;
  const auto x0 = vertex(x, 0), x1 = vertex(x, 1), x2 = vertex(x, 2), x3 = vertex(x, 3);
  const candidates::Normals m{(x1 - x0).cross(x2 - x0), (x2 - x3).cross(x1 - x3)};
  return candidates::peer(x, m, candidates::Angle::atan2, theta, grad, hess) ? 0 : 1;
}
