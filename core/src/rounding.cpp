// Mesh results rounded to double (hinge/core/rounding.hpp), instantiated for every scalar type.
#include "hinge/core/rounding.hpp"

#include <algorithm>

namespace hinge {

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

}  // namespace hinge
