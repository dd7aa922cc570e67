// hinge::fast in a run-time scalar type, rounded to double (hinge/fast/rounded.hpp). The templates are
// instantiated elsewhere (instantiate_*.cpp); this unit only converts.
#include "hinge/fast/rounded.hpp"

#include <cmath>
#include <string>

#include "hinge/fast/assemble.hpp"
#include "hinge/fast/hinge_kernel.hpp"
#include "hinge/reference/errors.hpp"

namespace hinge::fast {
namespace {

template <class Scalar>
reference::RoundedTheta theta_in(const std::array<double, 12>& x) {
  const HingeDerivatives<Scalar> d = hinge_derivatives<Scalar>(x, true);
  return reference::round_theta(d.theta, d.grad, d.hess);
}

template <class Scalar>
reference::RoundedMesh mesh_in(const Mesh& deformed, const Mesh& rest, const Topology& topology,
                               const reference::EnergyParameters& parameters, unsigned request, int threads,
                               EdgeOrientation orientation) {
  reference::RoundedMesh r;
  MeshDerivatives<Scalar> m;
  {
    Assembler<Scalar> assembler(topology, orientation);
    auto coefficients = assembler.rest_state(rest, parameters, threads);
    assembler.evaluate(deformed, std::move(coefficients), parameters.model, request, threads, m);
  }  // the pattern and work arrays are freed before the conversion
  r.energy = reference::rounded_to_double(m.energy, "the energy");
  r.gradient.resize(static_cast<std::size_t>(m.gradient.size()));
  for (Eigen::Index i = 0; i < m.gradient.size(); ++i) r.gradient[i] = reference::rounded_to_double(m.gradient[i], "the gradient");
  m.gradient.resize(0);
  if (request & reference::want_hessian) {
    if constexpr (std::is_same_v<Scalar, double>) {
      const double* v = m.hessian.valuePtr();
      for (Eigen::Index i = 0; i < m.hessian.nonZeros(); ++i) reference::rounded_to_double(v[i], "the Hessian");
      r.hessian.swap(m.hessian);  // no copy (Eigen 3.4's SparseMatrix has no move assignment)
    } else {
      Eigen::SparseMatrix<double> h(m.hessian.rows(), m.hessian.cols());
      h.resizeNonZeros(m.hessian.nonZeros());
      std::copy(m.hessian.outerIndexPtr(), m.hessian.outerIndexPtr() + m.hessian.outerSize() + 1, h.outerIndexPtr());
      std::copy(m.hessian.innerIndexPtr(), m.hessian.innerIndexPtr() + m.hessian.nonZeros(), h.innerIndexPtr());
      for (Eigen::Index i = 0; i < m.hessian.nonZeros(); ++i) h.valuePtr()[i] = reference::rounded_to_double(m.hessian.valuePtr()[i], "the Hessian");
      r.hessian.swap(h);
    }
  }
  // Eigen 3.4's SparseMatrix has no move assignment: a caller that assigns this result (as `hinge
  // hessian` does) would copy the matrix, doubling the peak memory. Marked as an Eigen rvalue, the
  // assignment swaps instead. (So do not copy the returned value: use it, move it or assign it.)
  r.hessian.markAsRValue();
  return r;
}

}  // namespace

reference::RoundedTheta hinge_derivatives_rounded(const ScalarType& type, const std::array<double, 12>& x) {
  return visit_scalar_type(type, [&]<class Scalar>() { return theta_in<Scalar>(x); });
}

reference::RoundedMesh assemble_rounded(const ScalarType& type, const Mesh& deformed, const Mesh& rest,
                                        const Topology& topology, const reference::EnergyParameters& parameters,
                                        unsigned request, int threads, EdgeOrientation orientation) {
  return visit_scalar_type(type, [&]<class Scalar>() {
    return mesh_in<Scalar>(deformed, rest, topology, parameters, request, threads, orientation);
  });
}

}  // namespace hinge::fast
