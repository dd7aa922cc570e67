// hinge::fast's entry points refuse a floating-point environment that breaks exact arithmetic
// (hinge/core/fp_environment.hpp): the per-hinge kernel, its span form, and the mesh assembly.
#include <gtest/gtest.h>

#include <vector>

#include "fast_support.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/fast/assemble.hpp"
#include "hinge/fast/hinge_kernel.hpp"
#include "hinge/reference/assemble.hpp"
#include "support/fp_environment.hpp"

namespace {

using hinge::test::ScopedFpEnvironment;
using hinge::test::Setting;

const std::array<double, 12> kHinge = {0.125, 0.75,  -0.5,    -0.25, 0.0625, 0.0,
                                       1.0,   0.125, -0.0625, 0.625, -0.875, 0.375};

TEST(FastFpEnvironment, PerHingeKernelsRefuseABrokenEnvironment) {
  const std::vector<std::array<double, 12>> many(4, kHinge);
  std::vector<hinge::fast::HingeDerivatives<double>> out(4);
  for (Setting s : hinge::test::kAllSettings) {
    ScopedFpEnvironment env(s);
    EXPECT_THROW(hinge::fast::hinge_derivatives<double>(kHinge), hinge::EnvironmentError);
    EXPECT_THROW(hinge::fast::hinge_derivatives<long double>(kHinge), hinge::EnvironmentError);
    EXPECT_THROW(hinge::fast::hinge_derivatives<double>(many, out), hinge::EnvironmentError);
  }
  EXPECT_NO_THROW(hinge::fast::hinge_derivatives<double>(kHinge));
}

TEST(FastFpEnvironment, MeshAssemblyRefusesABrokenEnvironment) {
  const hinge::Mesh rest = hinge::test::bumpy_grid(5, 1), deformed = hinge::test::bumpy_grid(5, 2);
  const hinge::Topology topology = hinge::build_topology(rest);
  const auto coefficients = hinge::reference::rest_state<double>(rest, topology, {hinge::Model::tan, 1.0, 0});
  hinge::fast::Assembler<double> assembler(topology);
  for (Setting s : hinge::test::kAllSettings) {
    ScopedFpEnvironment env(s);
    EXPECT_THROW(assembler.evaluate(deformed, coefficients, hinge::Model::tan, hinge::want_all, 1),
                 hinge::EnvironmentError);
  }
  EXPECT_NO_THROW(assembler.evaluate(deformed, coefficients, hinge::Model::tan, hinge::want_all, 1));
}

}  // namespace
