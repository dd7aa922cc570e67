// The conditioning of a hinge's bending term (hinge/oracle/conditioning.hpp, energy_conditioning): what
// central differences over the 24 coordinates of X and R must give. The Jacobian of psi with respect to X
// is its gradient, and that of its gradient the Hessian, so their scales are at least L times their norms
// (the rest coordinates only add); condition numbers do not change when X and R are translated together
// or scaled by a power of two; an exactly zero output has kappa 1.
#include <gtest/gtest.h>

#include <cmath>

#include "hinge/conformance/energy_inputs.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/conditioning.hpp"
#include "hinge/oracle/mesh.hpp"

namespace hinge::oracle {
namespace {

struct Certified {
  double energy = 0;
  std::array<double, 12> grad{};
  std::array<double, 144> hess{};
};

Certified certified(const std::array<double, 12>& x, const std::array<double, 12>& rest, const EnergyParameters& p) {
  const Mesh mx = hinge_mesh(x), mr = hinge_mesh(rest);
  const CertifiedMesh c = certified_mesh(mx, mr, build_topology(mx), p);
  Certified out;
  out.energy = c.rounded.energy;
  for (int i = 0; i < 12; ++i) out.grad[i] = c.rounded.gradient[i];
  for (Eigen::Index col = 0; col < c.rounded.hessian.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(c.rounded.hessian, col); it; ++it) {
      out.hess[12 * it.row() + it.col()] = it.value();
      out.hess[12 * it.col() + it.row()] = it.value();
    }
  return out;
}

Conditioning conditioning(const std::array<double, 12>& x, const std::array<double, 12>& rest,
                          const EnergyParameters& p) {
  const Certified c = certified(x, rest, p);
  return energy_conditioning(x, rest, p, false, c.energy, c.grad, c.hess);
}

std::vector<conformance::EnergyCase> some_cases() {
  std::vector<conformance::EnergyCase> out;
  const auto all = conformance::energy_inputs(2).cases;
  for (std::size_t i = 0; i < all.size(); i += 5) out.push_back(all[i]);
  return out;
}

TEST(EnergyConditioning, TheScalesAreAtLeastLTimesTheDerivativesWithRespectToX) {
  for (const auto& c : some_cases())
    for (Model model : {Model::shells, Model::tan}) {
      EnergyParameters p;
      p.model = model;
      try {
        const Certified v = certified(c.x, c.rest, p);
        const Conditioning k = energy_conditioning(c.x, c.rest, p, false, v.energy, v.grad, v.hess);
        // 1e-9: the differences' truncation (step 2^-100 L) and the certified outputs' rounding are far smaller
        EXPECT_GE(k.scale[0], k.length * scaled_norm(v.grad.data(), 12) * (1 - 1e-9)) << c.id;
        EXPECT_GE(k.scale[1], k.length * scaled_norm(v.hess.data(), 144) * (1 - 1e-9)) << c.id;
        EXPECT_GT(k.scale[2], 0) << c.id;
      } catch (const DomainError&) {
      }
    }
}

TEST(EnergyConditioning, DoesNotChangeWhenXAndRAreTranslatedOrScaledTogether) {
  int checked = 0;
  for (const auto& c : some_cases()) {
    if (c.category.rfind("well-shaped/", 0) != 0 && c.category.rfind("rotations/", 0) != 0) continue;
    EnergyParameters p;
    p.model = Model::shells;
    const Conditioning k = conditioning(c.x, c.rest, p);
    auto moved = [](std::array<double, 12> x, double factor, double shift) {
      for (double& v : x) v = v * factor + shift;  // exact: a power of two, and 64 with these coordinates' bits
      return x;
    };
    for (const auto& [factor, shift] : {std::pair{4.0, 0.0}, std::pair{1.0, 64.0}}) {
      const std::array<double, 12> x = moved(c.x, factor, shift), r = moved(c.rest, factor, shift);
      bool exact = true;
      for (int i = 0; i < 12; ++i)
        exact = exact && (x[i] - shift) / factor == c.x[i] && (r[i] - shift) / factor == c.rest[i];
      if (!exact) continue;
      const Conditioning m = conditioning(x, r, p);
      for (int g = 0; g < 3; ++g)  // 1e-6 relative: the differences of another step; kappa needs a digit or two
        EXPECT_NEAR(m.kappa[g], k.kappa[g], 1e-6 * k.kappa[g]) << c.id << " group " << g;
      ++checked;
    }
  }
  EXPECT_GT(checked, 0);
}

TEST(EnergyConditioning, AnExactlyZeroOutputHasKappaOne) {
  for (const auto& c : some_cases()) {
    if (c.category.find("/at-rest") == std::string::npos) continue;
    EnergyParameters p;
    p.model = Model::shells;
    const Certified v = certified(c.x, c.rest, p);
    ASSERT_EQ(v.energy, 0.0) << c.id;
    EXPECT_EQ(energy_conditioning(c.x, c.rest, p, false, v.energy, v.grad, v.hess).kappa[0], 1.0) << c.id;
  }
}

}  // namespace
}  // namespace hinge::oracle
