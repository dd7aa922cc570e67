// Pins: the listed vertices keep their initial positions. Their coordinates are removed from Newton's
// systems (Reduction, system.hpp) by the solver, so the effect itself adds nothing.
#include "effects_internal.hpp"

namespace hinge::sim::detail {
namespace {

class PinsEffect final : public Effect {
 public:
  std::string_view name() const override { return "pins"; }
  void add(const Eigen::VectorXd&, Evaluation&) override {}
};

}  // namespace

std::unique_ptr<Effect> make_pins(const Pins&) { return std::make_unique<PinsEffect>(); }

}  // namespace hinge::sim::detail
