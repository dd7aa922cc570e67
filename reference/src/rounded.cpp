// The reference in a run-time scalar type, rounded to double (hinge/reference/rounded.hpp). The
// templates are instantiated elsewhere (instantiate_*.cpp); this unit only converts.
#include "hinge/reference/rounded.hpp"

#include <cmath>
#include <string>

#include "hinge/reference/errors.hpp"
#include "hinge/reference/evaluate.hpp"

namespace hinge::reference {
namespace {

double rounded(const auto& value, const char* what) {
  const double d = to_double(value);
  if (!std::isfinite(d)) throw DomainError(std::string(what) + " is outside the range of double");
  return d;
}

template <class Scalar>
RoundedTheta theta_in(const std::array<double, 12>& x) {
  const ThetaDerivatives<Scalar> d = theta_derivatives<Scalar>(x, true);
  RoundedTheta r;
  r.theta = rounded(d.angle.theta, "theta");
  for (int i = 0; i < 12; ++i) r.grad[i] = rounded(d.grad[i], "the gradient");
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) r.hess[12 * i + j] = rounded(d.hess(i, j), "the Hessian");
  return r;
}

template <class Scalar>
RoundedMesh mesh_in(const Mesh& deformed, const Mesh& rest, const Topology& topology, const EnergyParameters& parameters,
                    unsigned request) {
  const auto coefficients = rest_state<Scalar>(rest, topology, parameters);
  const MeshDerivatives<Scalar> m = assemble<Scalar>(deformed, topology, coefficients, parameters.model, request);
  RoundedMesh r;
  r.energy = rounded(m.energy, "the energy");
  r.gradient.resize(static_cast<std::size_t>(m.gradient.size()));
  for (Eigen::Index i = 0; i < m.gradient.size(); ++i) r.gradient[i] = rounded(m.gradient[i], "the gradient");
  if (request & want_hessian) {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(m.hessian.nonZeros()));
    for (Eigen::Index c = 0; c < m.hessian.outerSize(); ++c)
      for (typename Eigen::SparseMatrix<Scalar>::InnerIterator it(m.hessian, c); it; ++it)
        t.emplace_back(it.row(), it.col(), rounded(it.value(), "the Hessian"));
    r.hessian.resize(m.hessian.rows(), m.hessian.cols());
    r.hessian.setFromTriplets(t.begin(), t.end());
  }
  return r;
}

// Calls f.template operator()<Scalar>() for the Scalar named by `type`, with MPFR's precision set.
template <class F>
auto with_scalar(const ScalarType& type, F&& f) {
  using K = ScalarType::Kind;
  switch (type.kind) {
    case K::kind_float: return f.template operator()<float>();
    case K::kind_double: return f.template operator()<double>();
    case K::kind_long_double: return f.template operator()<long double>();
    case K::kind_float128: return f.template operator()<float128>();
    case K::kind_bin128: return f.template operator()<bin128>();
    case K::kind_mpfr: set_mpfr_bits(type.mpfr_bits); return f.template operator()<mpfr>();
  }
  throw std::invalid_argument("unknown scalar type");
}

}  // namespace

RoundedTheta theta_derivatives_rounded(const ScalarType& type, const std::array<double, 12>& x) {
  return with_scalar(type, [&]<class Scalar>() { return theta_in<Scalar>(x); });
}

RoundedMesh assemble_rounded(const ScalarType& type, const Mesh& deformed, const Mesh& rest, const Topology& topology,
                             const EnergyParameters& parameters, unsigned request) {
  return with_scalar(type, [&]<class Scalar>() { return mesh_in<Scalar>(deformed, rest, topology, parameters, request); });
}

}  // namespace hinge::reference
