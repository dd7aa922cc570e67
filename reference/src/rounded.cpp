// The reference in a run-time scalar type, rounded to double (hinge/reference/rounded.hpp). The
// templates are instantiated elsewhere (instantiate_*.cpp); this unit only converts.
#include "hinge/reference/rounded.hpp"

#include "hinge/reference/evaluate.hpp"

namespace hinge::reference {
namespace {

template <class Scalar>
RoundedTheta theta_in(const std::array<double, 12>& x) {
  const ThetaDerivatives<Scalar> d = theta_derivatives<Scalar>(x, true);
  return round_theta(d.angle.theta, d.grad, d.hess);
}

template <class Scalar>
RoundedMesh mesh_in(const Mesh& deformed, const Mesh& rest, const Topology& topology,
                    const EnergyParameters& parameters, unsigned request) {
  const auto coefficients = rest_state<Scalar>(rest, topology, parameters);
  return round_mesh(assemble<Scalar>(deformed, topology, coefficients, parameters.model, request), request);
}

}  // namespace

RoundedTheta theta_derivatives_rounded(const ScalarType& type, const std::array<double, 12>& x) {
  return visit_scalar_type(type, [&]<class Scalar>() { return theta_in<Scalar>(x); });
}

RoundedMesh assemble_rounded(const ScalarType& type, const Mesh& deformed, const Mesh& rest, const Topology& topology,
                             const EnergyParameters& parameters, unsigned request) {
  return visit_scalar_type(
      type, [&]<class Scalar>() { return mesh_in<Scalar>(deformed, rest, topology, parameters, request); });
}

}  // namespace hinge::reference
