// tools/mesh_job.hpp: the options and the run shared by `hinge hessian` and `hinge oracle --mesh`.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>

#include "hinge/reference/scalar.hpp"
#include "methods.hpp"

namespace hinge::tools {

struct MeshOptions {
  std::string mesh, rest, energy, out, gradient;
  std::optional<double> k, young, poisson, thickness;
  int threads = 0;  // 0: all cores
  int repeat = 1;
};

// Registers --mesh, --rest, --energy, --k, --young, --poisson, --thickness, --out, --gradient,
// --threads, --repeat on `cmd`. With `mesh_required` false, --mesh is optional (hinge oracle).
void add_mesh_options(CLI::App* cmd, MeshOptions& o, bool mesh_required);

// Reads the meshes, evaluates with `method` in `scalar`, prints "energy <value>", writes the Matrix
// Market Hessian and the gradient if asked. Returns the exit status (0, or 1 with a message on
// standard error and no output file left behind). Throws std::invalid_argument for usage errors.
int run_mesh_job(const MeshOptions& o, const std::string& method, const ScalarType& scalar, const std::string& what);

// The same with another evaluator of the prepared job (hinge oracle --mesh: the certified oracle). It may
// throw what evaluate_mesh throws.
using MeshEvaluator = std::function<reference::RoundedMesh(const MeshJob&)>;
int run_mesh_job(const MeshOptions& o, const MeshEvaluator& evaluate, const std::string& what);

}  // namespace hinge::tools
