// The certified Gauss-Newton Hessian of a bending energy (Options::gauss_newton, hinge/oracle/mesh.hpp):
// sum over hinges of psi'' grad theta grad theta^T, not clamped. Checked on one-hinge meshes against the
// same product evaluated by the reference in MPFR at 1024 bits and rounded to double (1024 bits leave an
// error far below half an ulp of any output here, so the roundings agree unless a value lies within
// 2^-1000 of a midpoint), with the fast path and the enclosures alike; at rest psi' = 0 exactly for shells
// and tan, and then the Gauss-Newton Hessian is the exact one, bit for bit.
#include <gtest/gtest.h>

#include <array>
#include <map>

#include "hinge/conformance/inputs.hpp"
#include "hinge/core/scalar.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/reference/assemble.hpp"
#include "hinge/reference/evaluate.hpp"

namespace hinge::oracle {
namespace {

using Entries = std::map<std::pair<Eigen::Index, Eigen::Index>, double>;

Entries entries(const Eigen::SparseMatrix<double>& m) {
  Entries e;
  for (Eigen::Index c = 0; c < m.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, c); it; ++it) e[{it.row(), it.col()}] = it.value();
  return e;
}

// psi'' grad theta grad theta^T (upper triangle) in MPFR at 1024 bits, rounded to double.
Entries gauss_newton_at_1024_bits(const Mesh& deformed, const Mesh& rest, const EnergyParameters& p) {
  const unsigned previous = set_mpfr_bits(1024);
  const Topology t = build_topology(deformed);
  const auto coefficients = reference::rest_state<mpfr>(rest, t, p);
  std::array<double, 12> x{};
  for (int v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) x[3 * v + c] = deformed.vertices[v][c];
  const auto d = reference::theta_derivatives<mpfr>(x, false);
  const mpfr d2 = psi(p.model, coefficients[0], d.angle).d2;
  Entries out;
  for (int r = 0; r < 12; ++r)
    for (int c = r; c < 12; ++c) {
      const double v = static_cast<double>(mpfr(d2 * d.grad[r] * d.grad[c]));
      if (v != 0) out[{r, c}] = v;
    }
  set_mpfr_bits(previous);
  return out;
}

Entries nonzero(const Entries& e) {
  Entries out;
  for (const auto& [k, v] : e)
    if (v != 0) out[k] = v;
  return out;
}

TEST(GaussNewton, IsTheCorrectlyRoundedProductOfPsiSecondAndTheGradientOfTheta) {
  const std::vector<conformance::Case> cases = conformance::inputs();
  int checked = 0;
  for (std::size_t i = 0; i < cases.size(); i += 7) {  // every category, a few hinges each
    const conformance::Case& deformed = cases[i];
    const conformance::Case& rest = cases[(i + 40) % cases.size()];
    for (Model model : {Model::shells, Model::tan, Model::willmore, Model::bridson}) {
      EnergyParameters p;
      p.model = model;
      p.k = 0.75;
      const Mesh x = hinge_mesh(deformed.x), r = hinge_mesh(rest.x);
      const Topology t = build_topology(x);
      for (const bool fast : {true, false}) {
        Options o;
        o.gauss_newton = true;
        o.fast_path = fast;
        CertifiedMesh c;
        try {
          c = certified_mesh(x, r, t, p, want_hessian, o);
        } catch (const DomainError&) {
          continue;  // tan at a folded hinge, a result outside double
        }
        const std::string what =
            deformed.id + " on " + rest.id + " " + std::string(model_name(model)) + (fast ? " fast" : "");
        EXPECT_TRUE(c.uncertified.empty()) << what;
        EXPECT_EQ(nonzero(entries(c.rounded.hessian)), gauss_newton_at_1024_bits(x, r, p)) << what;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 300);
}

TEST(GaussNewton, AtRestIsTheExactHessianBitForBit) {
  for (const auto& m : conformance::meshes()) {
    const Topology t = build_topology(m.deformed);
    for (Model model : {Model::shells, Model::tan}) {
      EnergyParameters p;
      p.model = model;
      Options o;
      o.gauss_newton = true;
      const CertifiedMesh gn = certified_mesh(m.deformed, m.deformed, t, p, want_hessian, o);
      const CertifiedMesh exact = certified_mesh(m.deformed, m.deformed, t, p, want_hessian);
      EXPECT_EQ(entries(gn.rounded.hessian), entries(exact.rounded.hessian)) << m.name;
    }
  }
}

TEST(GaussNewton, AwayFromRestDiffersFromTheExactHessian) {
  const conformance::MeshCase m = conformance::meshes().front();
  const Topology t = build_topology(m.deformed);
  EnergyParameters p;
  p.model = Model::shells;
  Options o;
  o.gauss_newton = true;
  const CertifiedMesh gn = certified_mesh(m.deformed, m.rest, t, p, want_hessian, o);
  const CertifiedMesh exact = certified_mesh(m.deformed, m.rest, t, p, want_hessian);
  EXPECT_NE(entries(gn.rounded.hessian), entries(exact.rounded.hessian));
}

}  // namespace
}  // namespace hinge::oracle
