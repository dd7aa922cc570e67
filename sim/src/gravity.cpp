// Gravity: the body force m g on every lumped mass; potential -sum_v m_v g . x_v.
#include "effects_internal.hpp"

namespace hinge::sim::detail {
namespace {

class GravityEffect final : public Effect {
 public:
  GravityEffect(const Context& c, const Gravity& g) : force_(c.mass.size()) {
    for (Eigen::Index d = 0; d < force_.size(); ++d) force_[d] = c.mass[d] * g.g[static_cast<std::size_t>(d % 3)];
  }
  std::string_view name() const override { return "gravity"; }
  void add(const Eigen::VectorXd& x, Evaluation& out) override {
    if (out.request & 1u) out.energy -= force_.dot(x);
    if (out.request & 2u) out.gradient -= force_;
  }
  bool has_energy() const override { return true; }
  double energy(const Eigen::VectorXd& x) override { return -force_.dot(x); }

 private:
  Eigen::VectorXd force_;  // m_v g per coordinate
};

}  // namespace

std::unique_ptr<Effect> make_gravity(const Context& context, const Gravity& gravity) {
  return std::make_unique<GravityEffect>(context, gravity);
}

}  // namespace hinge::sim::detail
