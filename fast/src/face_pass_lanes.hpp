// The face pass of Algorithm 2 for double (line 8: N = (x1 - x0) x (x2 - x0), 2A = |N|, n = N / 2A), eight
// faces at a time in the lanes of lanes.hpp, in double-double: the edges exactly (two_diff), N and
// (2A)^2 = N . N in double-double, 1 / 2A and n each rounded to double once (the per-hinge kernel's
// arithmetic, hinge_kernel_lanes.hpp). Rounded once, the normals and 1 / 2A carry no more than half a
// unit of error into eq. (4); with Kahan's cross product and a normalization in double they carried
// about two, and the mesh Hessian's normwise error was 2.2 units of 2^-53 on the benchmark cloth
// instead of 1.7 (against the certified oracle). Included by assemble_double.cpp only.
//
// Range: as the rest of the mesh path (passes.hpp): edge lengths from about 2^-250 to 2^250, where N . N
// stays a normal double (below 2^-250 the double-double low parts underflow and N . N is only as accurate
// as a double).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "generic_kernel.hpp"
#include "lanes.hpp"
#include "passes.hpp"

namespace hinge::fast::detail {

// face_pass_body (passes.hpp) for faces [begin, end) of a double mesh.
template <class L>
HINGE_FAST_INLINE void face_pass_lanes(const Mesh& mesh, const Pattern& pattern, std::size_t begin, std::size_t end,
                                       std::array<double, 4>* face, char* suspect) {
  using D = DoubleDoubleOf<L>;
  using V = Vec<D>;
  const auto& faces = pattern.faces();
  const Point* vertices = mesh.vertices.data();
  auto lanes = [](const double* v) {
    L r;
    std::memcpy(&r, v, sizeof r);
    return r;
  };
  for (std::size_t first = begin; first < end; first += 8) {
    const std::size_t count = std::min<std::size_t>(8, end - first);
    alignas(64) double x[3][3][8];  // [vertex][component][lane]; the last face repeated in unused lanes
    for (std::size_t l = 0; l < 8; ++l) {
      const Pattern::Face& F = faces[first + std::min(l, count - 1)];
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) x[k][c][l] = vertices[F.v[k]][c];
    }
    V a, b;  // x1 - x0, x2 - x0, exactly
    for (int c = 0; c < 3; ++c) {
      a[c] = two_diff(lanes(x[1][c]), lanes(x[0][c]));
      b[c] = two_diff(lanes(x[2][c]), lanes(x[0][c]));
    }
    const V N = cross(a, b);
    const D S = dot(N, N);  // (2A)^2
    // 1 / 2A from y = 1 / sqrt of N . N in double and Newton's step y (1 + e/2), e = 1 - S y^2
    // (exact.hpp, rsqrt_correction), and n = N y (1 + e/2), each rounded once.
    const L y = L::broadcast(1) / root(N[0].hi * N[0].hi + N[1].hi * N[1].hi + N[2].hi * N[2].hi);
    const L half_e = rsqrt_correction(S, y);
    alignas(64) double out[5][8];  // n, 1 / 2A, certainty
    for (int c = 0; c < 3; ++c) {
      const L n = times_corrected(N[c], y, half_e).hi;
      std::memcpy(out[c], &n, sizeof n);
    }
    const L inverse = y + y * half_e;
    std::memcpy(out[3], &inverse, sizeof inverse);
    // The area is certainly nonzero where some component of N passes the filter (lanes.hpp,
    // area_certainty, as in the per-hinge kernel). Otherwise the face is flagged for the exact check.
    L certain = L::broadcast(-1);
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      certain = larger(certain, area_certainty(magnitude(a[i].hi * b[j].hi) + magnitude(a[j].hi * b[i].hi), N[k].hi));
    }
    std::memcpy(out[4], &certain, sizeof certain);
    for (std::size_t l = 0; l < count; ++l) {
      const std::size_t f = first + l;
      if (faces[f].highest < 0) {  // in no hinge
        suspect[f] = 0;
        continue;
      }
      face[f] = {out[0][l], out[1][l], out[2][l], out[3][l]};
      const bool finite = std::isfinite(out[3][l]) && std::isfinite(out[0][l] + out[1][l] + out[2][l]);
      suspect[f] = !(out[4][l] > 0) || !finite ? 1 : 0;
    }
  }
}

}  // namespace hinge::fast::detail
