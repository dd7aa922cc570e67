// The non-template parts of hinge::reference: model names, hinge coordinates and descriptions.
#include <stdexcept>
#include <string>

#include "hinge/reference/assemble_impl.hpp"

namespace hinge::reference {

std::string_view model_name(Model model) {
  switch (model) {
    case Model::shells: return "shells";
    case Model::tan: return "tan";
    case Model::willmore: return "willmore";
    case Model::bridson: return "bridson";
    case Model::viscoelastic: return "viscoelastic";
  }
  return "?";
}

Model parse_model(std::string_view name) {
  for (Model m : {Model::shells, Model::tan, Model::willmore, Model::bridson, Model::viscoelastic})
    if (model_name(m) == name) return m;
  throw std::invalid_argument("unknown energy '" + std::string(name) +
                              "': expected shells, tan, willmore, bridson or viscoelastic");
}

std::array<double, 12> hinge_coordinates(const Mesh& mesh, const Hinge& h) {
  std::array<double, 12> x;
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) x[3 * a + c] = mesh.vertices[h.x[a]][c];
  return x;
}

namespace detail {
std::string describe_hinge(const Topology& topology, Index hinge) {
  const Hinge& h = topology.hinges[hinge];
  const auto s = [](auto v) { return std::to_string(v); };
  return "hinge " + s(hinge) + " (edge " + s(h.x[1]) + "-" + s(h.x[2]) + ", faces " + s(h.upper) + " and " + s(h.lower) +
         "; OBJ numbering: vertices " + s(h.x[1] + 1) + "-" + s(h.x[2] + 1) + ", faces " + s(h.upper + 1) + " and " +
         s(h.lower + 1) + "): ";
}
}  // namespace detail

}  // namespace hinge::reference

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
