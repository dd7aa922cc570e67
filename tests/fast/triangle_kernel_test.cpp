// Eq. (7) (fast/src/triangle_kernel.hpp) on its own: the local triangle Hessians H^D, summed over the
// faces of a small mesh with the conditional transpose in exactly one face of every interior edge, plus
// the hinges' psi'' grad theta grad theta^T, give the sum of the per-hinge Hessians of hinge::reference.
// Broken on purpose: no transpose, or a transpose in both faces, must give a visibly wrong matrix.
#include <gtest/gtest.h>

#include <cmath>

#include "fast_support.hpp"
#include "hinge/reference/assemble.hpp"
#include "hinge/reference/evaluate.hpp"
#include "src/triangle_kernel.hpp"

namespace hinge::fast {
namespace {

enum class Dagger { owner_only, none, both };

// Dense Hessian of the mesh energy from eq. (7) and the per-edge outer products. The face of each edge
// that takes the dagger and owns the outer product is Edge::face[0].
Eigen::MatrixXd dense_from_triangles(const Mesh& mesh, const Topology& t,
                                     const std::vector<HingeCoefficients<double>>& c, Model model, Dagger dagger) {
  const Eigen::Index size = 3 * static_cast<Eigen::Index>(mesh.vertices.size());
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(size, size);
  std::vector<double> psi1(t.hinges.size()), psi2(t.hinges.size());
  for (std::size_t h = 0; h < t.hinges.size(); ++h) {
    const auto d = reference::theta_derivatives<double>(hinge_coordinates(mesh, t.hinges[h]), false);
    const auto p = psi(model, c[h], d.angle);
    psi1[h] = p.d1;
    psi2[h] = p.d2;
  }
  auto point = [&](Index v) { return Vec3<double>{mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]}; };
  auto face_normal = [&](Index f, Vec3<double>& n_out, double& inv2A) {
    const auto& v = mesh.faces[f];
    const Vec3<double> a = vsub(point(v[1]), point(v[0])), b = vsub(point(v[2]), point(v[0]));
    const Vec3<double> N{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double A2 = std::sqrt(vdot(N, N));
    n_out = {N[0] / A2, N[1] / A2, N[2] / A2};
    inv2A = 1 / A2;
  };
  auto add = [&](Index u, Index v, const Block3<double>& B) {  // B at (u, v) and B^T at (v, u)
    for (int r = 0; r < 3; ++r)
      for (int s = 0; s < 3; ++s) {
        H(3 * u + r, 3 * v + s) += B[r][s];
        H(3 * v + s, 3 * u + r) += B[r][s];
      }
  };
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const auto& v = mesh.faces[f];
    Vec3<double> n;
    double inv2A;
    face_normal(static_cast<Index>(f), n, inv2A);
    TriangleGeometry<double> g;
    triangle_geometry(point(v[0]), point(v[1]), point(v[2]), n, inv2A, g);
    std::array<double, 3> cc{};
    unsigned owns = 0;
    for (int i = 0; i < 3; ++i) {
      const Index e = t.face_edges[f][i];
      const Index h = t.hinge_of_edge[e];
      if (h < 0) continue;
      cc[i] = psi1[h];
      if (t.edges[e].face[0] == static_cast<Index>(f)) owns |= 1u << i;
    }
    const unsigned mask = dagger == Dagger::owner_only ? owns : dagger == Dagger::both ? 7u : 0u;
    std::array<Columns3<double>, 3> diag, off;
    triangle_hessian(g, cc, mask, 0u, diag, off);  // columns; no block mirrored
    for (int i = 0; i < 3; ++i) {
      for (int r = 0; r < 3; ++r)  // diag: upper triangle given; the mesh sum is symmetric
        for (int s = r; s < 3; ++s) {
          H(3 * v[i] + r, 3 * v[i] + s) += diag[i][s][r];
          if (s != r) H(3 * v[i] + s, 3 * v[i] + r) += diag[i][s][r];
        }
      Block3<double> B;
      for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) B[r][s] = off[i][s][r];
      add(v[i], v[(i + 1) % 3], B);
    }
    for (int k = 0; k < 3; ++k) {
      if (!((owns >> k) & 1u)) continue;
      const Index h = t.hinge_of_edge[t.face_edges[f][k]];
      const Edge& e = t.edges[t.face_edges[f][k]];
      const Index other = e.face[1];
      const Index s = mesh.faces[other][e.local[1]];
      Vec3<double> nt;
      double inv2At;
      face_normal(other, nt, inv2At);
      std::array<Vec3<double>, 4> gr;
      hinge_gradient(g, k, point(v[(k + 1) % 3]), point(v[(k + 2) % 3]), point(s), nt, inv2At, gr);
      const Index idx[4] = {v[k], v[(k + 1) % 3], v[(k + 2) % 3], s};
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          for (int r = 0; r < 3; ++r)
            for (int q = 0; q < 3; ++q) H(3 * idx[a] + r, 3 * idx[b] + q) += psi2[h] * gr[a][r] * gr[b][q];
    }
  }
  return H;
}

Eigen::MatrixXd dense_reference(const Mesh& mesh, const Topology& t, const std::vector<HingeCoefficients<double>>& c,
                                Model model) {
  const auto m = reference::assemble<double>(mesh, t, c, model);
  const Eigen::SparseMatrix<double> full = m.hessian.selfadjointView<Eigen::Upper>();
  return Eigen::MatrixXd(full);
}

TEST(TriangleKernel, DaggerInExactlyOneFaceGivesTheHingeSum) {
  const Mesh rest = test::bumpy_grid(6, 31), deformed = test::bumpy_grid(6, 32);
  const Topology t = build_topology(rest);
  for (Model model : {Model::tan, Model::shells}) {
    const auto c = reference::rest_state<double>(rest, t, {model, 0.8, 0});
    const Eigen::MatrixXd want = dense_reference(deformed, t, c, model);
    const Eigen::MatrixXd got = dense_from_triangles(deformed, t, c, model, Dagger::owner_only);
    // Plain double here (no compensated cross products): a few units each way; 16 units of 2^-53.
    EXPECT_LE((got - want).norm(), 16 * 0x1p-53 * want.norm()) << model_name(model);
    // The mesh sum is symmetric although no face's diagonal blocks are.
    EXPECT_LE((got - got.transpose()).norm(), 16 * 0x1p-53 * want.norm());
  }
}

TEST(TriangleKernel, MissingOrDoubledDaggerIsWrong) {
  // Break it on purpose: without the transpose, or with it in both faces, the R terms of every interior
  // edge add up to c (N_k + N~_k^T) instead of c (N_k + N~_k): an error of the size of the R terms.
  const Mesh rest = test::bumpy_grid(6, 33), deformed = test::bumpy_grid(6, 34);
  const Topology t = build_topology(rest);
  const auto c = reference::rest_state<double>(rest, t, {Model::tan, 0.8, 0});
  const Eigen::MatrixXd want = dense_reference(deformed, t, c, Model::tan);
  for (Dagger d : {Dagger::none, Dagger::both}) {
    const Eigen::MatrixXd got = dense_from_triangles(deformed, t, c, Model::tan, d);
    EXPECT_GT((got - want).norm(), 1e-3 * want.norm());
  }
}

TEST(TriangleKernel, HingeGradientOfSmallTrianglesStaysFinite) {
  // A hinge at 2^-400: 1 / (l 2A) would be 2^1200 (it overflowed), the coefficients l / 2A, (e . e') /
  // (l 2A) are ~2^400. The faces' n and 1 / 2A are formed in long double here (the mesh's face pass would
  // square 2A: out of its range at this size) and rounded once.
  const std::array<double, 12> unit{0.5, 1, 0.25, 0, 0, 0, 1, 0, 0, 0.375, -1, 0.5};
  for (int k : {0, -400, 400}) {
    std::array<double, 12> x;
    for (int i = 0; i < 12; ++i) x[i] = std::ldexp(unit[i], k);
    auto point = [&x](int v) { return Vec3<double>{x[3 * v], x[3 * v + 1], x[3 * v + 2]}; };
    auto face = [&x](int a, int b, int c, Vec3<double>& n, double& inv2A) {  // (x_b - x_a) x (x_c - x_a)
      long double u[3], v[3];
      for (int i = 0; i < 3; ++i) {
        u[i] = static_cast<long double>(x[3 * b + i]) - x[3 * a + i];
        v[i] = static_cast<long double>(x[3 * c + i]) - x[3 * a + i];
      }
      const long double N[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      const long double A2 = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
      n = {static_cast<double>(N[0] / A2), static_cast<double>(N[1] / A2), static_cast<double>(N[2] / A2)};
      inv2A = static_cast<double>(1 / A2);
    };
    Vec3<double> n, nt;
    double inv2A, inv2At;
    face(0, 1, 2, n, inv2A);    // upper face (x0, x1, x2): its local edge 0 is the hinge edge x1 -> x2
    face(3, 2, 1, nt, inv2At);  // lower face (x3, x2, x1)
    TriangleGeometry<double> g;
    triangle_geometry(point(0), point(1), point(2), n, inv2A, g);
    std::array<Vec3<double>, 4> gr;
    hinge_gradient(g, 0, point(1), point(2), point(3), nt, inv2At, gr);  // p, q, r, s = x0, x1, x2, x3
    Eigen::Matrix<double, 12, 1> got;
    for (int v = 0; v < 4; ++v)
      for (int c = 0; c < 3; ++c) got[3 * v + c] = gr[v][c];
    set_mpfr_bits(256);
    const auto want = reference::theta_derivatives<mpfr>(x, false).grad;
    for (int i = 0; i < 12; ++i) ASSERT_TRUE(std::isfinite(got[i])) << k;
    // Plain double: n and 1/2A rounded once, about six roundings in each coefficient: 16 units of 2^-53,
    // as above.
    Eigen::Matrix<double, 12, 1> exact;
    for (int i = 0; i < 12; ++i) exact[i] = to_double(want[i]);
    EXPECT_LE((got - exact).norm(), 16 * 0x1p-53 * exact.norm()) << k;
  }
}

}  // namespace
}  // namespace hinge::fast
