// hinge/core/samples.hpp: meshes built in code, reproducibly from a seed: the grid triangulation of
// docs/contract.md's scene format, and the benchmark's cloth (the paper's section 7 uses 11^2 to 81^2
// vertices). Random well-shaped hinges: hinge/reference/evaluate.hpp (well-shapedness is the reference's).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hinge/core/mesh.hpp"

namespace hinge {

// The faces of an nx x ny grid of vertices i + nx j: each cell (i, j) split along its diagonal from (i, j) to
// (i + 1, j + 1) into (p, q, r) and (p, r, s), p = (i, j), q = (i + 1, j), r = (i + 1, j + 1), s = (i, j + 1),
// cells in row order (i fastest): counter-clockwise seen from +z when i runs along +x and j along +y.
std::vector<std::array<Index, 3>> grid_faces(int nx, int ny);

// The grid mesh of the scene format (docs/contract.md, "grid"): vertex i + nx j at
// center + (i / (nx - 1) - 1/2) lx a + (j / (ny - 1) - 1/2) ly b, (a, b) the plane's axes ("xy": x, y;
// "xz": x, z; "yz": y, z), faces of grid_faces. Throws std::invalid_argument for nx or ny below 2, a
// non-positive size or another plane.
Mesh grid_mesh(int nx, int ny, double lx, double ly, const std::array<double, 3>& center, const std::string& plane);

// A unit square of n x n vertices, jittered in the plane by up to a tenth of the spacing and bumped out of
// it (z = 0.1 sin(6x) cos(5y), plus a little noise) so that every angle is nonzero, faces of grid_faces.
// Vertices in row order (a spatially coherent order, as meshers produce). `seed` varies the jitter: the
// benchmark's rest state is seed 1, its deformed state seed 2.
Mesh cloth(int n, unsigned seed);

}  // namespace hinge
