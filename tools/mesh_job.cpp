// hinge hessian / hinge oracle --mesh: reading the meshes, writing the results (tools/mesh_job.hpp).
#include "mesh_job.hpp"

#include "hinge/io/atomic_file.hpp"
#include "hinge/io/matrix_market.hpp"
#include "hinge/io/number.hpp"
#include "hinge/io/obj.hpp"

namespace hinge::tools {

void add_mesh_options(CLI::App* cmd, MeshOptions& o, bool mesh_required) {
  auto* mesh = cmd->add_option("--mesh", o.mesh, "Deformed mesh (OBJ: v and f lines)");
  if (mesh_required) mesh->required();
  cmd->add_option("--rest", o.rest, "Rest mesh, same faces (default: the deformed mesh itself)");
  cmd->add_option("--energy", o.energy, "Bending energy: tan, shells (also willmore, bridson; docs/quantities.md)");
  cmd->add_option("--k", o.k, "Bending stiffness k");
  cmd->add_option("--young", o.young, "Young's modulus Y (k = Y h^3 / (24 (1 - nu^2)), eq. (11))");
  cmd->add_option("--poisson", o.poisson, "Poisson's ratio nu, in (-1, 0.5]");
  cmd->add_option("--thickness", o.thickness, "Shell thickness h");
  cmd->add_option("--out", o.out, "Write the energy Hessian here (Matrix Market, coordinate real symmetric)");
  cmd->add_option("--gradient", o.gradient, "Write the energy gradient here (3n numbers, one per line)");
  cmd->add_option("--threads", o.threads, "Threads (default 0: all cores); never changes an output bit");
  cmd->add_option("--repeat", o.repeat, "Evaluate N times (for timing from outside); outputs from the last")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--allow-no-hinges", o.allow_no_hinges,
                "Accept a mesh without an interior edge (its energy is 0); without this flag it is an error");
}

namespace {

// k from --k, or from --young/--poisson/--thickness by eq. (11) (hinge/core/bending_problem.hpp checks the
// values). Usage errors throw std::invalid_argument.
BendingProblem problem(const MeshOptions& o) {
  const bool material = o.young || o.poisson || o.thickness;
  if (o.k && material) throw std::invalid_argument("give either --k or --young/--poisson/--thickness, not both");
  if (o.k) return bending_problem({*o.k, "--k"}, o.energy, "--energy");
  if (!(o.young && o.poisson && o.thickness))
    throw std::invalid_argument("give --k K, or all three of --young Y --poisson NU --thickness H");
  return bending_problem({*o.young, "--young"}, {*o.poisson, "--poisson"}, {*o.thickness, "--thickness"}, o.energy,
                         "--energy");
}

}  // namespace

MeshJob load_mesh_job(const MeshOptions& o) {
  if (o.energy.empty()) throw std::invalid_argument("--energy is required (tan or shells)");
  MeshJob job;
  job.parameters = problem(o).parameters();
  job.threads = resolve_threads(o.threads, "--threads");
  job.request = want_energy | (o.gradient.empty() ? 0u : want_gradient) | (o.out.empty() ? 0u : want_hessian);
  job.deformed = io::read_obj(o.mesh);
  if (!o.rest.empty()) job.rest = io::read_obj(o.rest);
  job.topology = build_topology(job.deformed);
  check_bending_mesh(job.topology, job.deformed, job.rest ? &*job.rest : nullptr,
                     {o.mesh, o.rest, "--allow-no-hinges", o.allow_no_hinges});
  return job;
}

int write_mesh_outputs(const MeshOptions& o, const RoundedMesh& result) {
  std::optional<io::AtomicFile> hessian_file, gradient_file;
  if (!o.out.empty())
    io::write_matrix_market(hessian_file.emplace(o.out).stream(), result.hessian,
                            "hinge: Hessian of the bending energy; lower triangle, 1-based, global index 3 v + c");
  if (!o.gradient.empty()) io::write_numbers(gradient_file.emplace(o.gradient).stream(), result.gradient);
  if (hessian_file) hessian_file->commit();
  if (gradient_file) gradient_file->commit();
  std::cout << "energy " << io::format_double(result.energy) << std::endl;
  return std::cout ? exit_done : exit_invalid_input;
}

}  // namespace hinge::tools
