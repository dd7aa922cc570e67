// Algorithm 2 on a mesh scaled by a power of two (hinge/fast/assemble.hpp; docs/numerics.md): the rest
// state is the same bits, the energy the same, the gradient exactly 2^-k and the Hessian exactly 2^-2k times
// the unscaled mesh's, for scalings inside the range evaluated as is (2^+-5, 2^+-12) and far outside it
// (2^+-100, 2^+-300: there the mesh is evaluated scaled; beyond, the Hessian of a unit mesh reaches
// the subnormals), in double and in the generic kernel's types.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "fast_support.hpp"
#include "hinge/fast/assemble.hpp"

namespace hinge::fast {
namespace {

Mesh scaled(const Mesh& m, int k) {
  Mesh s = m;
  for (auto& v : s.vertices)
    for (double& c : v) c = std::ldexp(c, k);
  return s;
}

// The same number, sign of zero included (long double: its 80 bits, not the padding around them).
template <class Scalar>
bool same_bits(const Scalar& a, const Scalar& b) {
  using std::signbit;
  return a == b && signbit(a) == signbit(b);
}

template <class Scalar>
void expect_exactly_scaled(int k, Model model) {
  const Mesh rest = test::bumpy_grid(7, 11), deformed = test::bumpy_grid(7, 12, 1.5);
  const Topology t = build_topology(rest);
  Assembler<Scalar> a(t);
  const auto c = a.rest_state(rest, {model, 0.7, 0});
  const auto f = a.evaluate(deformed, c, model, want_all, 2);
  const auto c_scaled = a.rest_state(scaled(rest, k), {model, 0.7, 0});
  const auto g = a.evaluate(scaled(deformed, k), c_scaled, model, want_all, 2);
  const std::string what = "2^" + std::to_string(k) + ", " + std::string(model_name(model));
  ASSERT_EQ(c.size(), c_scaled.size());
  for (std::size_t h = 0; h < c.size(); ++h) {
    ASSERT_TRUE(same_bits(c[h].a, c_scaled[h].a)) << what << ", hinge " << h;
    ASSERT_TRUE(same_bits(c[h].theta_bar, c_scaled[h].theta_bar)) << what << ", hinge " << h;
  }
  EXPECT_TRUE(same_bits(f.energy, g.energy)) << what;
  using std::ldexp;
  for (Eigen::Index i = 0; i < f.gradient.size(); ++i)
    ASSERT_TRUE(same_bits(Scalar(ldexp(f.gradient[i], -k)), g.gradient[i])) << what << ", gradient " << i;
  ASSERT_EQ(f.hessian.nonZeros(), g.hessian.nonZeros());
  for (Eigen::Index i = 0; i < f.hessian.nonZeros(); ++i)
    ASSERT_TRUE(same_bits(Scalar(ldexp(ldexp(f.hessian.valuePtr()[i], -k), -k)), g.hessian.valuePtr()[i]))
        << what << ", Hessian value " << i;
}

TEST(MeshScaling, PowerOfTwoScalingIsExactInDouble) {
  for (int k : {-300, -100, -12, -5, 5, 12, 100, 300})
    for (Model model : {Model::tan, Model::shells}) expect_exactly_scaled<double>(k, model);
}

TEST(MeshScaling, PowerOfTwoScalingIsExactInLongDoubleAndBin128) {
  for (int k : {-300, -12, 12, 300}) {
    expect_exactly_scaled<long double>(k, Model::tan);
    expect_exactly_scaled<bin128>(k, Model::tan);
  }
}

}  // namespace
}  // namespace hinge::fast
