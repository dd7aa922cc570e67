// hinge/reference/assemble.hpp: a mesh's bending energy E = sum_i psi_i(theta_i) (eq. 1), its gradient
// and Hessian (eqs. 2-3), assembled hinge by hinge: the plain baseline that hinge::fast is measured
// against. Each hinge adds its 10 upper 3x3 blocks (4 diagonal, 6 off-diagonal) as triplets; the
// matrix is compressed once at the end (10E block updates, the paper's section 4.2).
//
// The Hessian is stored as its upper triangle (row <= col), 3n x 3n, global index 3 v + c: use it as
// H.selfadjointView<Eigen::Upper>().
#pragma once

#include <Eigen/SparseCore>
#include <vector>

#include "hinge/reference/energy.hpp"
#include "hinge/reference/mesh.hpp"

namespace hinge::reference {

// What to compute; anything not requested is left empty (and costs nothing).
enum Request : unsigned { want_energy = 1u, want_gradient = 2u, want_hessian = 4u, want_all = 7u };

struct EnergyParameters {
  Model model = Model::tan;
  double k = 1;            // bending stiffness (or bending_stiffness(Y, nu, h), eq. 11)
  double k_d_over_dt = 0;  // viscoelastic only: k_d / dt
};

template <class Scalar>
struct MeshDerivatives {
  Scalar energy = 0;
  Eigen::Matrix<Scalar, Eigen::Dynamic, 1> gradient;  // dE/dx, 3n (empty unless requested)
  Eigen::SparseMatrix<Scalar> hessian;                // upper triangle of d2E/dx2 (empty unless requested)
};

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

// The 12 coordinates of hinge h, in the order x0, x1, x2, x3.
std::array<double, 12> hinge_coordinates(const Mesh& mesh, const Hinge& h);

#define HINGE_REFERENCE_ASSEMBLE_EXTERN(S)                                                                  \
  extern template std::vector<HingeCoefficients<S>> rest_state<S>(const Mesh&, const Topology&,             \
                                                                  const EnergyParameters&);                 \
  extern template void set_previous_state<S>(std::vector<HingeCoefficients<S>>&, const Mesh&, const Topology&); \
  extern template MeshDerivatives<S> assemble<S>(const Mesh&, const Topology&,                              \
                                                 const std::vector<HingeCoefficients<S>>&, Model, unsigned);
HINGE_FOR_EACH_SCALAR(HINGE_REFERENCE_ASSEMBLE_EXTERN)
#undef HINGE_REFERENCE_ASSEMBLE_EXTERN

}  // namespace hinge::reference
