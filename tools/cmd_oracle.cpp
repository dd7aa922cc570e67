// hinge oracle [--input FILE] [--output FILE]           hinges as JSON Lines, like hinge eval
// hinge oracle --mesh X.obj ... (options of hinge hessian)  a whole mesh
// For now the oracle is the reference evaluated in MPFR at 256 bits (at least; 257 as Boost sets it),
// each output rounded to the nearest double; certification by interval arithmetic is issue 6.
#include "commands.hpp"
#include "hinge_stream.hpp"
#include "mesh_job.hpp"
#include "methods.hpp"

namespace hinge::tools {

namespace {
constexpr unsigned oracle_bits = 256;
}

Action add_oracle(CLI::App& app) {
  auto* cmd = app.add_subcommand("oracle", "High-precision values rounded to double, for hinges or a whole mesh");
  struct Options {
    std::string input, output;
    MeshOptions mesh;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--input", o->input, "Input JSON Lines file (default: standard input)");
  cmd->add_option("--output", o->output, "Output JSON Lines file (default: standard output)");
  add_mesh_options(cmd, o->mesh, false);
  cmd->footer("Evaluates the reference in MPFR at 256 bits and rounds every output to the nearest double.");
  return [o]() -> int {
    const ScalarType scalar{ScalarType::Kind::kind_mpfr, oracle_bits};
    if (!o->mesh.mesh.empty()) return run_mesh_job(o->mesh, "reference", scalar, "oracle");
    return run_hinge_stream(o->input, o->output,
                            [&](const std::array<double, 12>& x) { return evaluate_hinge("reference", scalar, x); },
                            "oracle");
  };
}

}  // namespace hinge::tools
