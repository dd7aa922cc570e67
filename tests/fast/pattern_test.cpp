// The block pattern (hinge/fast/pattern.hpp): the same structure as hinge::reference::assemble's matrix,
// consistent block addressing, and the raw block view.
#include <gtest/gtest.h>

#include "fast_support.hpp"
#include "hinge/fast/pattern.hpp"
#include "hinge/reference/assemble.hpp"

namespace hinge::fast {
namespace {

// The octahedron: closed, every vertex of degree 4, some (x0, x3) pairs are edges themselves.
Mesh octahedron() {
  Mesh m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// A strip of three faces and a face touching it at one vertex (in no hinge: it writes nothing).
Mesh strip() {
  Mesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.2}, {2, 1, 0}, {3, 3, 1}, {4, 3, 1}};
  m.faces = {{0, 1, 2}, {1, 3, 2}, {3, 1, 4}, {4, 5, 6}};
  return m;
}

void expect_same_structure(const Mesh& mesh) {
  const Topology t = build_topology(mesh);
  const Pattern p(t);
  const auto coefficients = reference::rest_state<double>(mesh, t, {});
  const auto r = reference::assemble<double>(mesh, t, coefficients, Model::tan);
  const Eigen::SparseMatrix<double> m = p.make_matrix<double>();
  ASSERT_EQ(m.nonZeros(), r.hessian.nonZeros());
  EXPECT_TRUE(std::equal(m.outerIndexPtr(), m.outerIndexPtr() + m.outerSize() + 1, r.hessian.outerIndexPtr()));
  EXPECT_TRUE(std::equal(m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros(), r.hessian.innerIndexPtr()));
  EXPECT_TRUE(p.matches(m));
  // Every block's entries are where the compressed structure says they are.
  for (std::size_t b = 0; b < p.vertex_count(); ++b)
    for (std::int64_t j = p.block_start()[b]; j < p.block_start()[b + 1]; ++j) {
      const Index a = p.block_rows()[j];
      const SlotIndex base = p.find_block(a, static_cast<Index>(b));
      ASSERT_GE(base, 0);
      for (int c = 0; c < 3; ++c)
        for (int rr = 0; rr < 3; ++rr) {
          if (static_cast<std::size_t>(a) == b && rr > c) continue;
          const SlotIndex k = p.entry(base, static_cast<Index>(b), rr, c);
          EXPECT_GE(k, m.outerIndexPtr()[3 * b + c]);
          EXPECT_LT(k, m.outerIndexPtr()[3 * b + c + 1]);
          EXPECT_EQ(m.innerIndexPtr()[k], 3 * a + rr);
        }
    }
}

TEST(Pattern, SameStructureAsTheReferenceAssembly) {
  expect_same_structure(test::bumpy_grid(7, 61));
  expect_same_structure(octahedron());
  expect_same_structure(strip());
}

TEST(Pattern, RawBlocksMirrorTheCompressedValues) {
  const Mesh mesh = test::bumpy_grid(4, 62);
  const Topology t = build_topology(mesh);
  const Pattern p(t);
  Eigen::SparseMatrix<double> m = p.make_matrix<double>();
  for (Eigen::Index k = 0; k < m.nonZeros(); ++k) m.valuePtr()[k] = static_cast<double>(k + 1);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(Eigen::SparseMatrix<double>(m.selfadjointView<Eigen::Upper>()));
  const auto blocks = p.blocks(m.valuePtr());
  ASSERT_EQ(blocks.size(), p.block_rows().size());
  for (std::size_t b = 0; b < p.vertex_count(); ++b)
    for (std::int64_t j = p.block_start()[b]; j < p.block_start()[b + 1]; ++j) {
      const Index a = p.block_rows()[j];
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) EXPECT_EQ(blocks[j][3 * c + r], dense(3 * a + r, 3 * b + c));
    }
}

TEST(Pattern, OwnershipFollowsTheEdgeOrientation) {
  const Mesh mesh = test::bumpy_grid(5, 63);
  const Topology t = build_topology(mesh);
  for (EdgeOrientation o : {EdgeOrientation::first_face, EdgeOrientation::second_face}) {
    const Pattern p(t, o);
    std::vector<int> owners(t.hinges.size(), 0);
    std::vector<Index> owner(t.hinges.size(), -1);
    for (std::size_t f = 0; f < p.faces().size(); ++f)
      for (int k = 0; k < 3; ++k)
        if ((p.faces()[f].owns >> k) & 1u) {
          ++owners[p.faces()[f].hinge[k]];
          owner[p.faces()[f].hinge[k]] = static_cast<Index>(f);
        }
    for (std::size_t h = 0; h < t.hinges.size(); ++h) {
      EXPECT_EQ(owners[h], 1) << h;  // exactly one face per interior edge
      const Edge& e = t.edges[t.hinges[h].edge];
      EXPECT_EQ(owner[h], o == EdgeOrientation::first_face ? e.face[0] : e.face[1]);
      EXPECT_EQ(p.hinges()[h].other_face, o == EdgeOrientation::first_face ? e.face[1] : e.face[0]);
    }
  }
}

}  // namespace
}  // namespace hinge::fast
