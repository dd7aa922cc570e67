// A public implementation's failure mode: theta = acos(n . n~) with the sign of (n x n~) . e0. Near flat
// (n . n~ within u of 1) and near folded (within u of -1) acos loses half the digits of theta, or all
// of them: `hinge conform` must reject it there (categories near-flat and near-folded).
#include "peer_formulas.hpp"

extern "C" HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12],
                                                      double hess[144]) {
  return candidates::peer(x, candidates::hinge_edge_normals(x), candidates::Angle::acos, theta, grad, hess) ? 0 : 1;
}
