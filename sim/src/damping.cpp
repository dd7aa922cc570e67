// Damping, its mass part: the drag force -c M v. Backward Euler's step x+ = x + dt v+ turns it into the
// dissipation potential c / (2 dt) (x+ - x)^T M (x+ - x) of the incremental potential (docs/simulator.md).
// The bending part (the paper's section 5, k_d / dt a (phi - phi_hat)^2) lives in the bending effect,
// which evaluates it with the elastic part in one pass, as the paper does.
#include "effects_internal.hpp"

namespace hinge::sim::detail {
namespace {

class DampingEffect final : public Effect {
 public:
  DampingEffect(const Context& c, const Damping& d)
      : weight_(c.dt > 0 ? Eigen::VectorXd(d.mass / c.dt * c.mass) : Eigen::VectorXd::Zero(c.mass.size())),
        start_(c.mass.size()), diagonal_(diagonal_slots(*c.sparsity)) {}
  std::string_view name() const override { return "damping"; }
  void begin_step(const Eigen::VectorXd& x, const Eigen::VectorXd&) override { start_ = x; }
  void add(const Eigen::VectorXd& x, Evaluation& out) override {
    const Eigen::VectorXd d = x - start_;
    if (out.request & 1u) out.energy += 0.5 * d.dot(weight_.cwiseProduct(d));
    if (out.request & 2u) out.gradient += weight_.cwiseProduct(d);
    if (out.request & 4u)
      for (std::size_t k = 0; k < diagonal_.size(); ++k)
        out.hessian[static_cast<std::size_t>(diagonal_[k])] += weight_[static_cast<Eigen::Index>(k)];
  }

 private:
  Eigen::VectorXd weight_;  // c M / dt per coordinate
  Eigen::VectorXd start_;   // the state at the start of the step
  std::vector<Slot> diagonal_;
};

}  // namespace

std::unique_ptr<Effect> make_damping(const Context& context, const Damping& damping) {
  return std::make_unique<DampingEffect>(context, damping);
}

}  // namespace hinge::sim::detail
