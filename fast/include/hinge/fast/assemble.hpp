// hinge/fast/assemble.hpp: Algorithm 2 (and Algorithm 1 for the rest state), the combined loop over
// triangles that assembles a mesh's bending energy E = sum_i psi_i(theta_i) (eq. (1)), its gradient
// (eq. (2)) and Hessian (eq. (3)), in parallel and deterministic.
//
// The passes, each citing Algorithm 2:
//   faces    per face: N = e_1 x e_2, 2A = |N|, n (line 8; theta needs both normals of every edge first)
//   hinges   per interior edge: tan(theta/2) by eq. (12) and theta (lines 1-4), psi, psi', psi'' (line 5),
//            the energy (eq. (1))
//   assembly per face: cos(alpha_i), 1/h_i, m_i (lines 9-11), eq. (7) with the conditional transpose
//            (lines 12-14); per owned interior edge: grad theta (eq. (4), line 16), the force psi' grad theta
//            (eq. (2), line 17) and psi'' grad theta grad theta^T (lines 18-19), whose blocks among the
//            face's vertices join H^D before the scatter (6F + 4E block updates, section 4.2)
// Only what is requested is computed: energy alone stops after the hinge pass; the gradient alone skips
// eq. (7). The viscoelastic model evaluates grad theta and Hess theta once (its two parts live in psi).
//
// Output: hinge::MeshDerivatives (the same layout as hinge::reference::assemble: gradient 3n,
// Hessian upper triangle, row <= col, compressed columns, global index 3 v + c), the Hessian's structure
// from the Pattern (pattern.hpp): evaluate() writes straight into its values array.
//
// Threads: an evaluation runs on as many threads as asked, and its outputs are bit-for-bit the same for any
// thread count (every output entry receives the same contributions in the same order:
// src/assembler_impl.hpp explains how). The worker threads are kept by the Assembler between evaluations.
//
// Errors are found on the way (a floating-point filter flags possibly degenerate faces and infinite
// energies) and then decided exactly, hinge by hinge in order, with hinge::reference's checks and
// messages: InputError or DomainError naming the first offending hinge, its edge and faces.
//
#pragma once

#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "hinge/core/energy.hpp"
#include "hinge/core/results.hpp"
#include "hinge/core/scalar.hpp"
#include "hinge/fast/pattern.hpp"

namespace hinge::fast {

namespace detail {
template <class Scalar>
class Workspace;  // the pattern, the threads and the work arrays (src/assembler_impl.hpp)
}  // namespace detail

// Algorithm 2 for one topology: the pattern and the work arrays are built once and reused by every
// evaluation (no allocation after the first). Not thread-safe itself: one evaluation at a time (each
// runs on as many threads as asked; the worker threads are kept between evaluations and joined by the
// destructor; a copy gets its own). `topology` must outlive the Assembler.
template <class Scalar>
class Assembler {
 public:
  explicit Assembler(const Topology& topology, EdgeOrientation orientation = EdgeOrientation::first_face);
  ~Assembler();
  Assembler(const Assembler& other);
  Assembler& operator=(const Assembler& other);
  Assembler(Assembler&&) noexcept;
  Assembler& operator=(Assembler&&) noexcept;

  const Pattern& pattern() const;
  const Topology& topology() const;

  // Algorithm 1 on the rest mesh: a = 3 |e_bar|^2 / A_bar, theta_bar, phi_bar = 2 tan(theta_bar / 2)
  // (eq. (12)), k and k_d / dt from `parameters`, per hinge in Topology::hinges order. Throws InputError
  // for a degenerate rest hinge, DomainError for a rest hinge folded flat under an energy infinite at pi.
  std::vector<HingeCoefficients<Scalar>> rest_state(const Mesh& rest, const EnergyParameters& parameters,
                                                    int threads = 1);
  // Viscoelastic model: phi_hat of every hinge from the mesh at the previous time step.
  void set_previous_state(std::vector<HingeCoefficients<Scalar>>& coefficients, const Mesh& previous, int threads = 1);

  // Algorithm 2: what `request` asks (want_energy | want_gradient | want_hessian) into `out`;
  // out.hessian keeps its storage when it already has this pattern.
  void evaluate(const Mesh& deformed, const std::vector<HingeCoefficients<Scalar>>& coefficients, Model model,
                unsigned request, int threads, MeshDerivatives<Scalar>& out);
  // The same, consuming the coefficients: they are freed as soon as psi has been evaluated, before the
  // Hessian is allocated, which lowers the peak memory of a one-off evaluation (`hinge hessian`).
  void evaluate(const Mesh& deformed, std::vector<HingeCoefficients<Scalar>>&& coefficients, Model model,
                unsigned request, int threads, MeshDerivatives<Scalar>& out);
  MeshDerivatives<Scalar> evaluate(const Mesh& deformed, const std::vector<HingeCoefficients<Scalar>>& coefficients,
                                   Model model, unsigned request = want_all, int threads = 1);

 private:
  std::unique_ptr<detail::Workspace<Scalar>> work_;
};

// Convenience: one evaluation with a pattern built for it.
template <class Scalar>
MeshDerivatives<Scalar> assemble(const Mesh& deformed, const Topology& topology,
                                 const std::vector<HingeCoefficients<Scalar>>& coefficients, Model model,
                                 unsigned request = want_all, int threads = 1,
                                 EdgeOrientation orientation = EdgeOrientation::first_face) {
  Assembler<Scalar> a(topology, orientation);
  return a.evaluate(deformed, coefficients, model, request, threads);
}

#define HINGE_FAST_ASSEMBLE_EXTERN(S) extern template class Assembler<S>;
HINGE_FOR_EACH_SCALAR(HINGE_FAST_ASSEMBLE_EXTERN)
#undef HINGE_FAST_ASSEMBLE_EXTERN

}  // namespace hinge::fast
