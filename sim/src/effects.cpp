// The effects a scene names, in the contract's order (hinge/sim/effect.hpp).
#include "effects_internal.hpp"

namespace hinge::sim {

std::vector<std::unique_ptr<Effect>> make_effects(const Context& context) {
  const Scene& s = *context.scene;
  std::vector<std::unique_ptr<Effect>> effects;
  if (s.gravity) effects.push_back(detail::make_gravity(context, *s.gravity));
  if (s.stretching) effects.push_back(detail::make_stretching(context));
  if (s.bending) effects.push_back(detail::make_bending(context, *s.bending, s.damping ? &*s.damping : nullptr));
  if (s.damping) effects.push_back(detail::make_damping(context, *s.damping));
  if (s.pins) effects.push_back(detail::make_pins(*s.pins));
  if (s.sphere) effects.push_back(detail::make_sphere(context, *s.sphere));
  if (s.load) effects.push_back(detail::make_load(*s.load));
  return effects;
}

Couplings couplings(const Scene& s) {
  Couplings c;
  c.vertex_blocks = s.sphere.has_value();
  c.faces = s.stretching.has_value() || s.bending.has_value();
  c.hinges = s.bending.has_value();
  return c;
}

bool projects(Treatment treatment, HessianTreatment scene, bool bending) {
  return treatment == Treatment::projected ||
         (treatment == Treatment::scene && bending && scene != HessianTreatment::exact);
}

namespace detail {

std::vector<Slot> diagonal_slots(const Sparsity& sparsity) {
  std::vector<Slot> slots(static_cast<std::size_t>(sparsity.size()));
  for (Eigen::Index d = 0; d < sparsity.size(); ++d) slots[static_cast<std::size_t>(d)] = sparsity.slot(d, d);
  return slots;
}

}  // namespace detail

}  // namespace hinge::sim
