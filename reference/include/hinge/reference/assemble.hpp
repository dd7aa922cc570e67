// hinge/reference/assemble.hpp: a mesh's bending energy E = sum_i psi_i(theta_i) (eq. (1)), its gradient
// and Hessian (eqs. (2)-(3)), assembled hinge by hinge: the plain baseline that hinge::fast is measured
// against. Each hinge adds its 10 upper 3x3 blocks (4 diagonal, 6 off-diagonal) as triplets; the
// matrix is compressed once at the end (10E block updates, the paper's section 4.2).
//
// The Hessian is stored as its upper triangle (row <= col), 3n x 3n, global index 3 v + c: use it as
// H.selfadjointView<Eigen::Upper>().
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "hinge/core/energy.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/core/results.hpp"
#include "hinge/reference/hinge_energy.hpp"

namespace hinge::reference {

// Algorithm 1 on the rest mesh (same faces as `topology`, same vertex count): a, theta_bar, phi_bar per
// hinge, in the order of topology.hinges. Throws InputError (naming the hinge's edge and faces) for a
// degenerate rest hinge, DomainError for a folded rest hinge under an energy infinite at pi.
template <HingeScalar Scalar>
std::vector<HingeCoefficients<Scalar>> rest_state(const Mesh& rest, const Topology& topology,
                                                  const EnergyParameters& parameters);

// For the viscoelastic model: sets phi_hat of every hinge from the mesh at the previous time step.
template <HingeScalar Scalar>
void set_previous_state(std::vector<HingeCoefficients<Scalar>>& coefficients, const Mesh& previous,
                        const Topology& topology);

// E, grad E and Hess E of the deformed mesh, hinge by hinge. Throws InputError / DomainError naming the
// hinge (its edge's vertices and its two faces).
template <HingeScalar Scalar>
MeshDerivatives<Scalar> assemble(const Mesh& deformed, const Topology& topology,
                                 const std::vector<HingeCoefficients<Scalar>>& coefficients, Model model,
                                 unsigned request = want_all);

#define HINGE_REFERENCE_ASSEMBLE_EXTERN(S)                                                                      \
  extern template std::vector<HingeCoefficients<S>> rest_state<S>(const Mesh&, const Topology&,                 \
                                                                  const EnergyParameters&);                     \
  extern template void set_previous_state<S>(std::vector<HingeCoefficients<S>>&, const Mesh&, const Topology&); \
  extern template MeshDerivatives<S> assemble<S>(const Mesh&, const Topology&,                                  \
                                                 const std::vector<HingeCoefficients<S>>&, Model, unsigned);
HINGE_FOR_EACH_SCALAR(HINGE_REFERENCE_ASSEMBLE_EXTERN)
#undef HINGE_REFERENCE_ASSEMBLE_EXTERN

}  // namespace hinge::reference
