// The non-template part of evaluate.hpp: the well-shaped test of docs/contract.md, and hinges that pass it.
#include <algorithm>
#include <cmath>
#include <random>

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

std::vector<std::array<double, 12>> well_shaped_hinges(int count, unsigned seed, double offset) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1), decade(-3, 3);
  std::vector<std::array<double, 12>> hinges;
  while (static_cast<int>(hinges.size()) < count) {
    std::array<double, 12> x;
    const double scale = std::pow(10.0, decade(rng)), shift = offset * unit(rng);
    for (double& c : x) c = shift + scale * unit(rng);
    if (well_shaped(x)) hinges.push_back(x);
  }
  return hinges;
}

}  // namespace hinge::reference
