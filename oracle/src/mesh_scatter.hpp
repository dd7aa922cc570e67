// oracle/src/mesh_scatter.hpp: one hinge's eq. (3) into the mesh Hessian's upper triangle, in the
// pattern and order of hinge::reference::assemble (private to hinge::oracle): the enclosures (mesh.cpp,
// T = Interval) and the fast path (mesh_fast_path.cpp, T = Bounded) sum the same terms in the same order.
#pragma once

#include <array>
#include <map>
#include <utility>

#include <Eigen/SparseCore>

#include "hinge/core/mesh.hpp"

namespace hinge::oracle::detail {

// local(row, col): the hinge's 12 x 12 entry (eq. (3)); each of the 10 upper blocks of the hinge's four
// vertices goes to its global block (transposed when the vertex order flips; a block of one global vertex
// twice takes both halves), added to what `hessian` holds there.
template <class T, class Local>
void scatter_hessian(const Hinge& hinge, Local local, std::map<std::pair<Eigen::Index, Eigen::Index>, T>& hessian) {
  for (int a4 = 0; a4 < 4; ++a4)
    for (int b4 = a4; b4 < 4; ++b4) {
      const Index va = hinge.x[a4], vb = hinge.x[b4];
      std::array<T, 9> B;
      for (int rr = 0; rr < 3; ++rr)
        for (int cc = 0; cc < 3; ++cc) {
          B[3 * rr + cc] = local(3 * a4 + rr, 3 * b4 + cc);
          if (a4 != b4 && va == vb)
            B[3 * rr + cc] = B[3 * rr + cc] + local(3 * b4 + rr, 3 * a4 + cc);  // one global vertex
        }
      const bool flip = va > vb;
      const Index row = flip ? vb : va, col = flip ? va : vb;
      for (int rr = 0; rr < 3; ++rr)
        for (int cc = 0; cc < 3; ++cc) {
          if (row == col && rr > cc) continue;
          const std::pair<Eigen::Index, Eigen::Index> key{3 * row + rr, 3 * col + cc};
          const T& v = flip ? B[3 * cc + rr] : B[3 * rr + cc];
          auto [it, inserted] = hessian.try_emplace(key, v);
          if (!inserted) it->second = it->second + v;
        }
    }
}

}  // namespace hinge::oracle::detail
