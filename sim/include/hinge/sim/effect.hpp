// hinge/sim/effect.hpp: one effect of a scene (gravity, stretching, bending, damping, pins, sphere, load),
// built only when the scene names it (make_effects). Each adds its part of the potential Newton minimizes
// (the total potential for a static solve; for a backward Euler step the incremental potential, whose
// inertial part the integrator adds) at a state x (3n coordinates, 3 v + c) into an Evaluation.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "hinge/core/mesh.hpp"
#include "hinge/sim/scene.hpp"
#include "hinge/sim/system.hpp"

namespace hinge::sim {

// Which Hessian an evaluation asks for (docs/simulator.md, "Newton"): `scene`, bending's as the scene's
// "hessian" treats it and every other effect's true Hessian (the fallback chain's first rung); `projected`,
// every element's Hessian (each hinge's, each StVK triangle's, each sphere contact's) projected to positive
// semidefinite (its second rung); `exact`, the true Hessian of every effect (what --dump-system writes).
enum class Treatment { scene, projected, exact };

// What one evaluation of the potential adds to (request: want_energy | want_gradient |
// want_hessian).
struct Evaluation {
  unsigned request = 7;
  Treatment treatment = Treatment::scene;
  double energy = 0;
  Eigen::VectorXd gradient;     // 3n
  std::vector<double> hessian;  // the Sparsity's values
};

// What the effects share: the scene, its topology and Hessian structure, the lumped masses (per
// coordinate), the time step (0 for a static solve) and the threads they may use.
struct Context {
  const Scene* scene = nullptr;
  const Topology* topology = nullptr;
  const Sparsity* sparsity = nullptr;
  Eigen::VectorXd mass;  // 3n: each vertex's lumped mass, three times
  double dt = 0;
  int threads = 1;
};

class Effect {
 public:
  virtual ~Effect() = default;
  virtual std::string_view name() const = 0;
  // Adds this effect's part of the potential at x (throws hinge::DomainError where it is infinite, as the
  // tan energy of a hinge folded flat).
  virtual void add(const Eigen::VectorXd& x, Evaluation& out) = 0;
  // Whether the effect has a potential energy of its own for summary.json, and its value at x.
  virtual bool has_energy() const { return false; }
  virtual double energy(const Eigen::VectorXd& /*x*/) { return 0; }
  // Called before each time step with its starting state (x, v).
  virtual void begin_step(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*v*/) {}
  // The largest fraction of the step dx from x that keeps the state admissible (the sphere: no vertex
  // enters), in (0, 1].
  virtual double max_step(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*dx*/) const { return 1; }
  // Checks the initial state x; throws hinge::InputError naming the scene's key.
  virtual void check_initial(const Eigen::VectorXd& /*x*/) const {}
};

// The effects the scene names, in the contract's order (gravity, stretching, bending, damping, pins,
// sphere, load). Throws hinge::InputError for a rest shape an effect cannot take (degenerate triangles,
// a rest hinge folded flat under the tan energy), naming the scene and the element.
std::vector<std::unique_ptr<Effect>> make_effects(const Context& context);

// The blocks of the Hessian the scene's named effects couple: the union of their stencils (a scene of
// gravity, load and damping alone has a diagonal Hessian; the sphere adds each vertex's 3 x 3 block,
// stretching every face's vertex pairs, bending those and each hinge's x0, x3).
Couplings couplings(const Scene& scene);

// Whether an element's Hessian is projected to positive semidefinite in an evaluation: always for
// `projected`; for `scene`, a hinge's as the scene's "hessian" says (`bending` true) and no other element's.
bool projects(Treatment treatment, HessianTreatment scene, bool bending);

}  // namespace hinge::sim
