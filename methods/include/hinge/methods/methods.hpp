// hinge/methods/methods.hpp: the evaluation methods by name (docs/contract.md: `hinge eval --method`,
// `hinge hessian --method`, the study's rows, the Python module), each in a scalar type chosen at run
// time (hinge/core/scalar.hpp), every output rounded to double. A name is parsed once into a Method;
// the calls below switch on it and go straight to the library that implements it.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "hinge/core/energy.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/core/method.hpp"
#include "hinge/core/results.hpp"
#include "hinge/core/scalar.hpp"

namespace hinge::methods {

// The methods' names live in hinge::core (hinge/core/method.hpp), beside the scalar types'.
using hinge::Method;
using hinge::method_name;
using hinge::method_names;
using hinge::parse_method;

// theta, grad theta, Hess theta of the hinge x (x0.x, ..., x3.z) by `method` in `scalar`, rounded to double.
// Throws hinge::InputError (degenerate or non-finite input) or hinge::DomainError (a result outside the range
// of double; for autodiff and symbolic also a NaN or infinity from an intermediate, which they do not rescale).
RoundedTheta evaluate_hinge(Method method, const ScalarType& scalar, const std::array<double, 12>& x);

// A whole mesh: what `request` asks (want_energy | want_gradient | want_hessian).
struct MeshInput {
  const Mesh* deformed = nullptr;
  const Mesh* rest = nullptr;  // same faces and vertex count (Algorithm 1's rest state)
  const Topology* topology = nullptr;
  EnergyParameters parameters;
  unsigned request = want_all;
  int threads = 1;  // hinge::fast only; never changes an output bit
};

namespace detail {
struct EvaluatorImpl;
}  // namespace detail

// A mesh evaluation prepared once and run any number of times (`hinge hessian --repeat`, the study's mesh
// level): the constructor runs Algorithm 1 on the rest mesh (and for fast builds the Hessian's pattern
// and the work arrays); evaluate() computes what input.request asks, kept in the scalar type;
// take_result() rounds the last evaluation to double. The meshes and topology of `input` must outlive it.
// Constructor and evaluate() throw as evaluate_hinge does, naming the hinge.
class MeshEvaluator {
 public:
  MeshEvaluator(Method method, const ScalarType& scalar, const MeshInput& input);
  ~MeshEvaluator();
  MeshEvaluator(MeshEvaluator&&) noexcept;
  MeshEvaluator& operator=(MeshEvaluator&&) noexcept;

  // One evaluation. `last`: none follows, so the per-hinge constants and (fast) the pattern may be freed as
  // soon as they have served, which lowers the peak memory; evaluate() may not be called again.
  void evaluate(bool last = false);
  // The last evaluation rounded to double, moved out (once per evaluation; see round_mesh on
  // assigning it). Throws DomainError for a result outside the range of double.
  RoundedMesh take_result();

 private:
  ScalarType scalar_;  // mpfr's precision is set again before each call (it is a global setting)
  std::unique_ptr<detail::EvaluatorImpl> impl_;
};

// One evaluation: MeshEvaluator(method, scalar, input), evaluate(true), take_result().
RoundedMesh evaluate_mesh(Method method, const ScalarType& scalar, const MeshInput& input);

}  // namespace hinge::methods
