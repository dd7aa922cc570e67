// Model names and the energies' error messages (hinge/core/energy.hpp).
#include "hinge/core/energy.hpp"

#include <stdexcept>
#include <string>

namespace hinge {

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

void throw_infinite_energy(Model model) {
  throw DomainError("the " + std::string(model_name(model)) +
                    " energy is infinite at theta = +-pi (hinge folded flat onto itself)");
}

void throw_folded_rest(Model model) {
  throw DomainError("rest hinge is folded flat (theta_bar = pi): the " + std::string(model_name(model)) +
                    " energy needs theta_bar in (-pi, pi) (eq. (10))");
}

void throw_folded_previous() { throw DomainError("the previous state is folded flat (theta_hat = pi)"); }

}  // namespace hinge
