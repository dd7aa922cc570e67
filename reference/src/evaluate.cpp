// The non-template part of evaluate.hpp: the well-shaped test of docs/contract.md.
#include <algorithm>

#include "hinge/reference/evaluate.hpp"
#include "hinge/reference/evaluate_impl.hpp"

namespace hinge::reference {

bool well_shaped(const std::array<double, 12>& x) {
  PreparedHinge<double> p;
  try {
    p = prepare_hinge<double>(x);
  } catch (const InputError&) {
    return false;
  }
  for (const Triangle<double>* t : {&p.stencil.upper, &p.stencil.lower}) {
    const double longest = std::max({t->l[0], t->l[1], t->l[2]});
    const double lowest = std::min({t->h[0], t->h[1], t->h[2]});
    if (lowest < 0.15 * longest) return false;
  }
  const double theta = std::abs(bend_angle(p.stencil, p.sign).theta);
  return theta >= 0.05 && theta <= 3.141592653589793 - 0.05;
}

}  // namespace hinge::reference
