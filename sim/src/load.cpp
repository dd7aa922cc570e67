// Load: a constant force f on each listed vertex; potential -sum f . x_v.
#include "effects_internal.hpp"

namespace hinge::sim::detail {
namespace {

class LoadEffect final : public Effect {
 public:
  explicit LoadEffect(const Load& l) : load_(l) {}
  std::string_view name() const override { return "load"; }
  void add(const Eigen::VectorXd& x, Evaluation& out) override {
    if (out.request & 1u) out.energy += energy(x);
    if (out.request & 2u)
      for (Index v : load_.vertices)
        for (int c = 0; c < 3; ++c) out.gradient[3 * v + c] -= load_.force[static_cast<std::size_t>(c)];
  }
  bool has_energy() const override { return true; }
  double energy(const Eigen::VectorXd& x) override {
    double e = 0;
    for (Index v : load_.vertices)
      for (int c = 0; c < 3; ++c) e -= load_.force[static_cast<std::size_t>(c)] * x[3 * v + c];
    return e;
  }

 private:
  Load load_;
};

}  // namespace

std::unique_ptr<Effect> make_load(const Load& load) { return std::make_unique<LoadEffect>(load); }

}  // namespace hinge::sim::detail
