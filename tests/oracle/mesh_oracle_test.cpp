// The certified mesh oracle (hinge/oracle/mesh.hpp): against the reference assembled in MPFR at 1024 bits
// and rounded, on the conformance meshes, for every energy; exact zeros at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "hinge/conformance/inputs.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/reference/rounded.hpp"

namespace hinge::oracle {
namespace {

std::map<std::pair<Eigen::Index, Eigen::Index>, double> entries(const Eigen::SparseMatrix<double>& m) {
  std::map<std::pair<Eigen::Index, Eigen::Index>, double> e;
  for (Eigen::Index c = 0; c < m.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, c); it; ++it) e[{it.row(), it.col()}] = it.value();
  return e;
}

TEST(MeshOracle, AgreesWithTheReferenceAt1024Bits) {
  for (const auto& m : conformance::meshes())
    for (Model model : {Model::shells, Model::tan, Model::willmore, Model::bridson}) {
      const Topology t = build_topology(m.deformed);
      EnergyParameters p;
      p.model = model;
      p.k = 0.75;
      const CertifiedMesh c = certified_mesh(m.deformed, m.rest, t, p);
      const RoundedMesh r = reference::assemble_rounded({ScalarType::Kind::kind_mpfr, 1024}, m.deformed, m.rest, t, p);
      const std::string what = m.name + " " + std::string(model_name(model));
      EXPECT_TRUE(c.uncertified.empty()) << what;
      EXPECT_EQ(c.rounded.energy, r.energy) << what;
      ASSERT_EQ(c.rounded.gradient.size(), r.gradient.size()) << what;
      for (std::size_t i = 0; i < r.gradient.size(); ++i)
        EXPECT_EQ(c.rounded.gradient[i], r.gradient[i]) << what << " " << i;
      const auto a = entries(c.rounded.hessian), b = entries(r.hessian);
      EXPECT_EQ(a.size(), b.size()) << what;
      for (const auto& [k, v] : b) {
        const auto it = a.find(k);
        ASSERT_NE(it, a.end()) << what;
        if (it->second == 0) {
          EXPECT_LE(std::fabs(v), 1e-250) << what;  // an exact zero; the reference has noise
        } else {
          EXPECT_EQ(it->second, v) << what << " (" << k.first << ", " << k.second << ")";
        }
      }
    }
}

TEST(MeshOracle, AtRestTheEnergyAndGradientAreExactlyZero) {
  for (const auto& m : conformance::meshes()) {
    const Topology t = build_topology(m.deformed);
    for (Model model : {Model::shells, Model::tan}) {
      EnergyParameters p;
      p.model = model;
      Options enclosures;  // the enclosures' machinery at rest (the fast path: oracle_fast_path_test)
      enclosures.fast_path = false;
      const CertifiedMesh c = certified_mesh(m.deformed, m.deformed, t, p, want_all, enclosures);
      EXPECT_EQ(c.rounded.energy, 0.0) << m.name;
      for (double g : c.rounded.gradient) EXPECT_EQ(g, 0.0) << m.name;
      EXPECT_TRUE(c.uncertified.empty()) << m.name;
      EXPECT_EQ(c.bits, Options{}.start_bits) << m.name;
    }
  }
}

TEST(MeshOracle, TanEnergyOnAFoldedHingeIsAnError) {
  Mesh m;
  m.vertices = {{0.5, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0.25, 0.5, 0}};
  m.faces = {{0, 1, 2}, {3, 2, 1}};
  Mesh rest = m;
  rest.vertices[3] = {0.5, -1, 0};
  const Topology t = build_topology(m);
  EnergyParameters p;
  p.model = Model::tan;
  EXPECT_THROW(certified_mesh(m, rest, t, p), DomainError);
  p.model = Model::shells;
  EXPECT_NO_THROW(certified_mesh(m, rest, t, p));
}

}  // namespace
}  // namespace hinge::oracle
