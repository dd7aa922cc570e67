// The evaluation methods by name (hinge/methods/methods.hpp).
#include "hinge/methods/methods.hpp"

#include <stdexcept>

#include "baselines.hpp"
#include "hinge/fast/rounded.hpp"
#include "hinge/reference/rounded.hpp"

namespace hinge::methods {

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

reference::RoundedTheta evaluate_hinge(Method method, const ScalarType& scalar, const std::array<double, 12>& x) {
  switch (method) {
    case Method::reference: return reference::theta_derivatives_rounded(scalar, x);
    case Method::fast: return fast::hinge_derivatives_rounded(scalar, x);
    case Method::autodiff:
    case Method::symbolic:
      return visit_scalar_type(scalar, [&]<class Scalar>() { return detail::baseline_hinge<Scalar>(method, x); });
  }
  throw std::invalid_argument("evaluate_hinge: unknown method");
}

reference::RoundedMesh evaluate_mesh(Method method, const ScalarType& scalar, const MeshInput& in) {
  switch (method) {
    case Method::reference:
      return reference::assemble_rounded(scalar, *in.deformed, *in.rest, *in.topology, in.parameters, in.request);
    case Method::fast:
      return fast::assemble_rounded(scalar, *in.deformed, *in.rest, *in.topology, in.parameters, in.request, in.threads);
    case Method::autodiff:
    case Method::symbolic:
      return visit_scalar_type(scalar, [&]<class Scalar>() { return detail::baseline_mesh<Scalar>(method, in); });
  }
  throw std::invalid_argument("evaluate_mesh: unknown method");
}

}  // namespace hinge::methods
