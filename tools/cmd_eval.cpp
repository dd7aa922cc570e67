// hinge eval [--method M] [--scalar S] [--cond] [--faithful] [--input FILE] [--output FILE] (docs/contract.md).
#include "commands.hpp"
#include "hinge/fast/faithful.hpp"
#include "hinge/io/jsonl.hpp"
#include "hinge/methods/methods.hpp"
#include "hinge/oracle/conditioning.hpp"
#include "hinge_stream.hpp"

namespace hinge::tools {

Action add_eval(CLI::App& app) {
  auto* cmd = app.add_subcommand("eval", "Evaluate theta, its gradient and Hessian for hinges given as JSON Lines");
  struct Options {
    std::string method = "reference", scalar = "double", input, output;
    bool cond = false, faithful = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--method", o->method, "Evaluation method: reference, fast, autodiff, symbolic")
      ->capture_default_str();
  cmd->add_option("--scalar", o->scalar, "Scalar type: float, double, long-double, dd, qd, float128, bin128, mpfr:BITS")
      ->capture_default_str();
  cmd->add_flag("--cond", o->cond,
                "Add to each result \"kappa\": {\"theta\", \"grad\", \"hess\"}, the condition numbers of the tolerance "
                "policy, L ||J_f||_F / ||f||_2 (docs/conformance.md), from the certified values");
  cmd->add_flag("--faithful", o->faithful,
                "The fast method's faithful mode (implies --method fast; double only): each output group within 1 "
                "unit of 2^-53 of the exact values, normwise (hinge/fast/faithful.hpp; 2.2 to 2.8 times the plain "
                "kernel's time)");
  cmd->add_option("--input", o->input, "Input JSON Lines file (default: standard input)");
  cmd->add_option("--output", o->output, "Output JSON Lines file (default: standard output)");
  cmd->footer(
      "Input, one object per line: {\"id\": \"...\", \"x\": [x0.x, x0.y, x0.z, x1.x, ..., x3.z]}.\n"
      "Output, same order: {\"id\", \"theta\", \"grad\": [12], \"hess\": [144, row-major]}, or {\"id\", \"error\"}.\n"
      "Every number is printed so that it reads back exactly. Exit: 0 all lines read, 1 I/O failure, 2 usage.");
  return [o, cmd]() -> int {
    const ScalarType scalar = parse_scalar_type(o->scalar);  // std::invalid_argument: usage error
    const bool method_given = cmd->count("--method") > 0;
    const methods::Method method =
        o->faithful && !method_given ? methods::Method::fast : methods::parse_method(o->method);
    if (o->faithful && (method != methods::Method::fast || scalar.kind != ScalarType::Kind::kind_double))
      throw std::invalid_argument("--faithful needs --method fast and --scalar double");
    return run_hinge_stream(
        o->input, o->output, "eval", [&](const std::string& id_json, const std::array<double, 12>& x) {
          const RoundedTheta r =
              o->faithful ? fast::faithful_derivatives_rounded(x) : methods::evaluate_hinge(method, scalar, x);
          if (!o->cond) return io::result_line(id_json, r);
          return io::result_line(id_json, r, oracle::certified_with_conditioning(x).conditioning.kappa);
        });
  };
}

}  // namespace hinge::tools
