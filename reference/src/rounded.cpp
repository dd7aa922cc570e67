// The reference in a run-time scalar type, rounded to double (hinge/reference/rounded.hpp). The
// templates are instantiated elsewhere (instantiate_*.cpp); this unit only converts.
#include "hinge/reference/rounded.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <string>

#include "hinge/reference/errors.hpp"
#include "hinge/reference/evaluate.hpp"

namespace hinge::reference {
namespace {

template <class Scalar>
RoundedTheta theta_in(const std::array<double, 12>& x) {
  const ThetaDerivatives<Scalar> d = theta_derivatives<Scalar>(x, true);
  return round_theta(d.angle.theta, d.grad, d.hess);
}

}  // namespace

template <HingeScalar Scalar>
RoundedMesh round_mesh(MeshDerivatives<Scalar>&& m, unsigned request) {
  RoundedMesh r;
  r.energy = rounded_to_double(m.energy, "the energy");
  r.gradient.resize(static_cast<std::size_t>(m.gradient.size()));
  for (Eigen::Index i = 0; i < m.gradient.size(); ++i) r.gradient[i] = rounded_to_double(m.gradient[i], "the gradient");
  m.gradient.resize(0);
  if (request & want_hessian) {
    m.hessian.makeCompressed();
    if constexpr (std::is_same_v<Scalar, double>) {
      const double* v = m.hessian.valuePtr();
      for (Eigen::Index i = 0; i < m.hessian.nonZeros(); ++i) rounded_to_double(v[i], "the Hessian");
      r.hessian.swap(m.hessian);  // no copy
    } else {
      Eigen::SparseMatrix<double> h(m.hessian.rows(), m.hessian.cols());
      h.resizeNonZeros(m.hessian.nonZeros());
      std::copy(m.hessian.outerIndexPtr(), m.hessian.outerIndexPtr() + m.hessian.outerSize() + 1, h.outerIndexPtr());
      std::copy(m.hessian.innerIndexPtr(), m.hessian.innerIndexPtr() + m.hessian.nonZeros(), h.innerIndexPtr());
      for (Eigen::Index i = 0; i < m.hessian.nonZeros(); ++i)
        h.valuePtr()[i] = rounded_to_double(m.hessian.valuePtr()[i], "the Hessian");
      r.hessian.swap(h);
    }
  }
  r.hessian.markAsRValue();
  return r;
}
#define HINGE_ROUND_MESH_INSTANTIATE(S) template RoundedMesh round_mesh<S>(MeshDerivatives<S>&&, unsigned);
HINGE_FOR_EACH_SCALAR(HINGE_ROUND_MESH_INSTANTIATE)
#undef HINGE_ROUND_MESH_INSTANTIATE

namespace {

template <class Scalar>
RoundedMesh mesh_in(const Mesh& deformed, const Mesh& rest, const Topology& topology, const EnergyParameters& parameters,
                    unsigned request) {
  const auto coefficients = rest_state<Scalar>(rest, topology, parameters);
  return round_mesh(assemble<Scalar>(deformed, topology, coefficients, parameters.model, request), request);
}

}  // namespace

RoundedTheta theta_derivatives_rounded(const ScalarType& type, const std::array<double, 12>& x) {
  return visit_scalar_type(type, [&]<class Scalar>() { return theta_in<Scalar>(x); });
}

RoundedMesh assemble_rounded(const ScalarType& type, const Mesh& deformed, const Mesh& rest, const Topology& topology,
                             const EnergyParameters& parameters, unsigned request) {
  return visit_scalar_type(type, [&]<class Scalar>() { return mesh_in<Scalar>(deformed, rest, topology, parameters, request); });
}

}  // namespace hinge::reference
