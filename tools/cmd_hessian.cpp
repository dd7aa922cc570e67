// hinge hessian --mesh X.obj [--rest R.obj] --energy tan|shells (--k K | --young Y --poisson NU
// --thickness H) [--method M] [--scalar S] [--out H.mtx] [--gradient G.txt] [--threads N] [--repeat N]
#include "commands.hpp"
#include "hinge/methods/methods.hpp"
#include "mesh_job.hpp"
#include "progress.hpp"

namespace hinge::tools {

Action add_hessian(CLI::App& app) {
  auto* cmd = app.add_subcommand("hessian", "Bending energy, gradient and Hessian of a whole mesh");
  struct Options {
    MeshOptions mesh;
    std::string method = "reference", scalar = "double";
  };
  auto o = std::make_shared<Options>();
  add_mesh_options(cmd, o->mesh, true);
  cmd->add_option("--method", o->method, "Evaluation method: reference, fast, autodiff, symbolic")
      ->capture_default_str();
  cmd->add_option("--scalar", o->scalar, "Scalar type: float, double, long-double, dd, qd, float128, bin128, mpfr:BITS")
      ->capture_default_str();
  cmd->footer(
      "Prints 'energy <value>'. Exit: 0 done; 1 invalid input (message names file and line, edge or face;\n"
      "no output file left behind); 2 usage error.");
  return [o]() {
    const ScalarType scalar = parse_scalar_type(o->scalar);  // std::invalid_argument: usage error
    const methods::Method method = methods::parse_method(o->method);
    return run_mesh_command("hessian", [&] {
      const MeshJob job = load_mesh_job(o->mesh);
      methods::MeshEvaluator evaluator(method, scalar, job.input());  // Algorithm 1 and the pattern, once
      Progress progress("hinge hessian: evaluations", static_cast<std::size_t>(o->mesh.repeat));
      for (int r = 0; r < o->mesh.repeat; ++r) {
        evaluator.evaluate(r + 1 == o->mesh.repeat);
        progress.update(static_cast<std::size_t>(r + 1));
      }
      return write_mesh_outputs(o->mesh, evaluator.take_result());
    });
  };
}

}  // namespace hinge::tools
