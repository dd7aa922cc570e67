// hinge/core/bending_problem.hpp: the one place where a bending problem given from outside is checked:
// the energy's name, k given or from (Y, nu, h) by eq. (11), one range per parameter, the mesh checks and
// the thread count. Every route (hinge hessian, hinge oracle --mesh, hinge conform --mesh, hinge.hessian,
// a scene) calls these with its own name for the parameter, so the sentences differ only in that name:
//
//   "--poisson: Poisson's ratio nu must be in (-1, 0.5], got 0.7"               command: exit status 2
//   "k=: the bending stiffness k must be finite and >= 0, got -1"               Python: ValueError
//   "scene.json: effects.bending.k: the bending stiffness k must be ..."        scene: exit status 1
//
// (the scene reader prefixes its file to what()). The ranges (the contract's "one range per parameter"):
// k finite and >= 0, Y finite and > 0, nu in (-1, 0.5], h finite and > 0.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "hinge/core/energy.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/core/mesh.hpp"

namespace hinge {

// A parameter out of range, an unknown or refused energy name, a thread count out of range: what() is
// "<name>: <why>", <name> the caller's name for the parameter ("--k", "k=", "effects.bending.k"). A
// std::invalid_argument, so that `hinge` reports it as a usage error (exit status 2) and the Python
// module as a ValueError without a catch of their own; a scene reader turns it into an InputError.
class ParameterError : public std::invalid_argument {
 public:
  ParameterError(std::string_view name, const std::string& why);
  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

// A value as given, with the name its route gives it (for the messages).
struct Parameter {
  double value;
  std::string_view name;
};

// ---- Energies

// Every bending energy name the project knows. The first five are hinge::Model's, in its order (the
// evaluators' energies psi(theta)); quadratic (Bergou et al. 2006) and custom (a candidate's own energy)
// exist only for the conformance of energies: no evaluator takes them, so Model does not list them.
enum class Energy { shells, tan, willmore, bridson, viscoelastic, quadratic, custom };

std::string_view energy_name(Energy energy);  // "shells", ..., "custom"
// The evaluators' Model for `energy`; std::nullopt for quadratic and custom.
std::optional<Model> evaluator_model(Energy energy);
// The names a command, hinge.hessian and a scene accept: "shells, tan, willmore, bridson" (for help texts).
std::string_view evaluated_energy_names();

// The energy of a command, hinge.hessian or a scene: shells, tan, willmore or bridson. ParameterError:
//   "<name>: unknown energy 'springs' (expected one of shells, tan, willmore, bridson)"
//   "<name>: the viscoelastic energy is library-only: it needs a previous state and a time step"
//   "<name>: the quadratic energy is conformance-only: hinge has no evaluator for it"
//   "<name>: the custom energy is conformance-only: it is a candidate's own energy"
Model parse_bending_energy(std::string_view value, std::string_view name);
// The energy a candidate is graded on (conformance of energies): also quadratic and custom; viscoelastic
// refused with the sentence above, an unknown name with the six names listed.
Energy parse_graded_energy(std::string_view value, std::string_view name);

// ---- Parameters: each returns the value when it is in range, else throws ParameterError.

double check_k(Parameter k);                  // "<name>: the bending stiffness k must be finite and >= 0, got V"
double check_young(Parameter young);          // "<name>: Young's modulus Y must be finite and > 0, got V"
double check_poisson(Parameter poisson);      // "<name>: Poisson's ratio nu must be in (-1, 0.5], got V"
double check_thickness(Parameter thickness);  // "<name>: the thickness h must be finite and > 0, got V"

// eq. (11), k = Y h^3 / (24 (1 - nu^2)), the only place it is computed from outside input: checks the
// three (messages above), then ParameterError "<young>, <poisson>, <thickness>: k = Y h^3 / (24 (1 -
// nu^2)) (eq. (11)) overflows double" where the quotient is not finite. 3 times a plate's stiffness in
// cylindrical bending: proofs/errata.md E8.
double stiffness_from_material(Parameter young, Parameter poisson, Parameter thickness);

// What an evaluation of the bending energy takes from outside, checked.
struct BendingProblem {
  Model energy = Model::tan;
  double k = 1;
  EnergyParameters parameters() const { return {energy, k, 0}; }
};

// The energy by name with k given (hinge conform --mesh, hinge.hessian, a scene with "k").
BendingProblem bending_problem(Parameter k, std::string_view energy, std::string_view energy_name);
// The energy by name with k from the material (hinge hessian --young --poisson --thickness, a scene without
// "k"). Which of the two a route takes, and what it says when both or neither are given, is the route's.
BendingProblem bending_problem(Parameter young, Parameter poisson, Parameter thickness, std::string_view energy,
                               std::string_view energy_name);

// ---- The mesh

// How a route names its meshes, and whether it accepts a mesh without a single interior edge.
struct MeshCheck {
  std::string_view deformed;      // prefixes messages on the deformed mesh ("X.obj"; "" for none)
  std::string_view rest;          // prefixes messages on the rest mesh ("R.obj"; "" for none)
  std::string_view allow_option;  // how to accept no interior edge: "--allow-no-hinges",
                                  // "allow_no_hinges=True"; "" if the route offers no way
  bool allow_no_hinges = false;
};

// After build_topology(deformed): InputError
//   "<deformed>: the mesh has no interior edge, so its bending energy is 0 whatever its shape (<allow_option>
//   if that is meant)"   (the parenthesis only with an allow_option; not at all with allow_no_hinges)
//   "<deformed or rest>: face 0 (OBJ face 1) (vertices 0, 1, 2) has zero area (collinear or coincident
//   vertices)"   (check_faces_nondegenerate, on the deformed mesh, then on `rest` unless null)
void check_bending_mesh(const Topology& topology, const Mesh& deformed, const Mesh* rest, const MeshCheck& check);

// ---- Threads

constexpr long long max_threads = 4096;
// The threads an evaluation uses: `requested`, or for 0 (the default of hinge hessian --threads and
// hinge.hessian(threads=)) all cores, at least 1. Never changes an output bit. ParameterError
// "<name>: threads must be in [0, 4096] (0: all cores), got V" otherwise.
int resolve_threads(long long requested, std::string_view name);

}  // namespace hinge
