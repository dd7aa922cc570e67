// hinge hessian / hinge oracle --mesh: a whole mesh's energy, gradient and Hessian (tools/mesh_job.hpp).
#include "mesh_job.hpp"

#include <cmath>
#include <iostream>
#include <optional>
#include <thread>

#include "commands.hpp"
#include "hinge/reference/errors.hpp"
#include "hinge/reference/obj.hpp"
#include "methods.hpp"
#include "output.hpp"
#include "progress.hpp"

namespace hinge::tools {

void add_mesh_options(CLI::App* cmd, MeshOptions& o, bool mesh_required) {
  auto* mesh = cmd->add_option("--mesh", o.mesh, "Deformed mesh (OBJ: v and f lines)");
  if (mesh_required) mesh->required();
  cmd->add_option("--rest", o.rest, "Rest mesh, same faces (default: the deformed mesh itself)");
  cmd->add_option("--energy", o.energy, "Bending energy: tan, shells (also willmore, bridson; docs/quantities.md)");
  cmd->add_option("--k", o.k, "Bending stiffness k");
  cmd->add_option("--young", o.young, "Young's modulus Y (k = Y h^3 / (24 (1 - nu^2)), eq. 11)");
  cmd->add_option("--poisson", o.poisson, "Poisson's ratio nu, in (-1, 1)");
  cmd->add_option("--thickness", o.thickness, "Shell thickness h");
  cmd->add_option("--out", o.out, "Write the energy Hessian here (Matrix Market, coordinate real symmetric)");
  cmd->add_option("--gradient", o.gradient, "Write the energy gradient here (3n numbers, one per line)");
  cmd->add_option("--threads", o.threads, "Threads (default: all cores); never changes an output bit")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--repeat", o.repeat, "Evaluate N times (for timing from outside); outputs from the last")
      ->check(CLI::PositiveNumber);
}

namespace {

// k from --k, or from --young/--poisson/--thickness by eq. (11). Usage errors throw std::invalid_argument.
double stiffness(const MeshOptions& o) {
  const bool material = o.young || o.poisson || o.thickness;
  if (o.k && material) throw std::invalid_argument("give either --k or --young/--poisson/--thickness, not both");
  if (o.k) {
    if (!std::isfinite(*o.k) || *o.k < 0) throw std::invalid_argument("--k must be finite and >= 0");
    return *o.k;
  }
  if (!(o.young && o.poisson && o.thickness))
    throw std::invalid_argument("give --k K, or all three of --young Y --poisson NU --thickness H");
  if (!std::isfinite(*o.young) || *o.young < 0) throw std::invalid_argument("--young must be finite and >= 0");
  if (!(*o.poisson > -1 && *o.poisson < 1)) throw std::invalid_argument("--poisson must be in (-1, 1)");
  if (!std::isfinite(*o.thickness) || *o.thickness <= 0) throw std::invalid_argument("--thickness must be > 0");
  const double k = reference::bending_stiffness(*o.young, *o.poisson, *o.thickness);  // eq. (11)
  if (!std::isfinite(k)) throw std::invalid_argument("k = Y h^3 / (24 (1 - nu^2)) overflows");
  return k;
}

void write_matrix_market(std::ostream& out, const Eigen::SparseMatrix<double>& upper) {
  out << "%%MatrixMarket matrix coordinate real symmetric\n"
      << "% hinge: Hessian of the bending energy; lower triangle, 1-based, global index 3 v + c\n"
      << upper.rows() << ' ' << upper.cols() << ' ' << upper.nonZeros() << '\n';
  std::string line;
  for (Eigen::Index c = 0; c < upper.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(upper, c); it; ++it) {
      line.clear();
      line += std::to_string(it.col() + 1);  // (row <= col) stored; (col, row) is in the lower triangle
      line += ' ';
      line += std::to_string(it.row() + 1);
      line += ' ';
      append_double(line, it.value());
      line += '\n';
      out << line;
    }
}

}  // namespace

int run_mesh_job(const MeshOptions& o, const std::string& method, const ScalarType& scalar, const std::string& what) {
  require_method(method);
  return run_mesh_job(o, [&](const MeshJob& job) { return evaluate_mesh(method, scalar, job); }, what);
}

int run_mesh_job(const MeshOptions& o, const MeshEvaluator& evaluate, const std::string& what) {
  if (o.energy.empty()) throw std::invalid_argument("--energy is required (tan or shells)");
  reference::EnergyParameters parameters;
  parameters.model = reference::parse_model(o.energy);
  if (parameters.model == reference::Model::viscoelastic)
    throw std::invalid_argument("--energy viscoelastic is available from the library, not from this command");
  parameters.k = stiffness(o);
  const int threads = o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  try {
    const Mesh deformed = read_obj(o.mesh);
    std::optional<Mesh> rest_storage;
    if (!o.rest.empty()) rest_storage = read_obj(o.rest);
    const Mesh& rest = rest_storage ? *rest_storage : deformed;
    const Topology topology = build_topology(deformed);
    check_faces_nondegenerate(deformed);
    if (&rest != &deformed) check_faces_nondegenerate(rest);

    MeshJob job{&deformed, &rest, &topology, parameters,
                reference::want_energy | (o.gradient.empty() ? 0u : reference::want_gradient) |
                    (o.out.empty() ? 0u : reference::want_hessian),
                threads};
    reference::RoundedMesh result;
    Progress progress("hinge " + what + ": evaluations", static_cast<std::size_t>(o.repeat));
    for (int r = 0; r < o.repeat; ++r) {
      result = evaluate(job);
      progress.update(static_cast<std::size_t>(r + 1));
    }

    // Outputs appear only when all of them are written.
    std::optional<AtomicFile> hessian_file, gradient_file;
    if (!o.out.empty()) write_matrix_market(hessian_file.emplace(o.out).stream(), result.hessian);
    if (!o.gradient.empty()) {
      auto& g = gradient_file.emplace(o.gradient).stream();
      std::string line;
      for (double v : result.gradient) {
        line.clear();
        append_double(line, v);
        line += '\n';
        g << line;
      }
    }
    if (hessian_file) hessian_file->commit();
    if (gradient_file) gradient_file->commit();
    std::cout << "energy " << format_double(result.energy) << std::endl;
    return std::cout ? exit_done : exit_invalid_input;
  } catch (const InputError& e) {
    std::cerr << "hinge " << what << ": " << e.what() << "\n";
  } catch (const DomainError& e) {
    std::cerr << "hinge " << what << ": " << e.what() << "\n";
  } catch (const std::ios_base::failure& e) {
    std::cerr << "hinge " << what << ": I/O error: " << e.what() << "\n";
  } catch (const std::filesystem::filesystem_error& e) {
    std::cerr << "hinge " << what << ": " << e.what() << "\n";
  } catch (const std::runtime_error& e) {
    std::cerr << "hinge " << what << ": " << e.what() << "\n";
  }
  return exit_invalid_input;
}

}  // namespace hinge::tools
