// The evaluation methods' names (hinge/core/method.hpp).
#include "hinge/core/method.hpp"

#include <stdexcept>

namespace hinge {
namespace {

constexpr Method kMethods[] = {Method::reference, Method::fast, Method::autodiff, Method::symbolic};

}  // namespace

std::string_view method_name(Method method) {
  switch (method) {
    case Method::reference: return "reference";
    case Method::fast: return "fast";
    case Method::autodiff: return "autodiff";
    case Method::symbolic: return "symbolic";
  }
  return "?";
}

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (Method m : kMethods) names.emplace_back(method_name(m));
  return names;
}

Method parse_method(std::string_view name) {
  std::string known;
  for (Method m : kMethods) {
    if (method_name(m) == name) return m;
    known += (known.empty() ? "" : ", ") + std::string(method_name(m));
  }
  throw std::invalid_argument("unknown method '" + std::string(name) + "': expected one of " + known);
}

}  // namespace hinge
