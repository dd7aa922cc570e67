// tools/mesh_job.hpp: the options, the input files and the output files shared by `hinge hessian` and
// `hinge oracle --mesh`. A mesh goes one way: read (load_mesh_job: OBJ, topology, checks), evaluate (the
// command calls hinge::methods or hinge::oracle), write (write_mesh_outputs: Matrix Market, gradient,
// energy).
#pragma once

#include <CLI/CLI.hpp>
#include <iostream>
#include <optional>
#include <string>

#include "commands.hpp"
#include "hinge/core/bending_problem.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/methods/methods.hpp"

namespace hinge::tools {

struct MeshOptions {
  std::string mesh, rest, energy, out, gradient;
  std::optional<double> k, young, poisson, thickness;
  long long threads = 0;  // 0: all cores
  int repeat = 1;
  bool allow_no_hinges = false;  // a mesh without an interior edge is accepted (its energy is 0)
};

// Registers --mesh, --rest, --energy, --k, --young, --poisson, --thickness, --out, --gradient,
// --threads, --repeat, --allow-no-hinges on `cmd`. With `mesh_required` false, --mesh is optional (hinge oracle).
void add_mesh_options(CLI::App* cmd, MeshOptions& o, bool mesh_required);

// The meshes read and checked, with the energy's parameters: what an evaluation takes.
struct MeshJob {
  Mesh deformed;
  std::optional<Mesh> rest;  // --rest; else the deformed mesh is the rest shape
  Topology topology;
  EnergyParameters parameters;
  unsigned request = want_energy;
  int threads = 1;
  methods::MeshInput input() const {
    return {&deformed, rest ? &*rest : &deformed, &topology, parameters, request, threads};
  }
};

// Parses --energy and the stiffness (std::invalid_argument for a usage error), reads the meshes and builds
// the topology (hinge::InputError naming the file and line, the face or the edge).
MeshJob load_mesh_job(const MeshOptions& o);

// Writes the Matrix Market Hessian (--out) and the gradient (--gradient), both or neither, then prints
// "energy <value>". Returns the exit status.
int write_mesh_outputs(const MeshOptions& o, const RoundedMesh& result);

// Runs body() (which returns an exit status); an InputError, DomainError or I/O failure becomes the message
// "hinge <what>: ..." on standard error and exit status 1, with no output file left behind.
template <class Body>
int run_mesh_command(const std::string& what, Body&& body) {
  try {
    return body();
  } catch (const InputError& e) {
    std::cerr << "hinge " << what << ": " << e.what() << "\n";
  } catch (const DomainError& e) {
    std::cerr << "hinge " << what << ": " << e.what() << "\n";
  } catch (const std::ios_base::failure& e) {
    std::cerr << "hinge " << what << ": I/O error: " << e.what() << "\n";
  } catch (const std::runtime_error& e) {  // files that cannot be written (io::AtomicFile), filesystem errors
    std::cerr << "hinge " << what << ": " << e.what() << "\n";
  }
  return exit_invalid_input;
}

}  // namespace hinge::tools
