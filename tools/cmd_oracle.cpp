// hinge oracle [--input FILE] [--output FILE] [--report-precision] [--max-bits N]   hinges as JSON Lines
// hinge oracle --mesh X.obj ... (options of hinge hessian)                           a whole mesh
// Certified: every output is the double nearest to the exact value for the input doubles
// (hinge/oracle/oracle.hpp, oracle/README.md). An output that cannot be certified within --max-bits is
// printed as the double nearest to its enclosure's midpoint and flagged on its line with the enclosure
// ("uncertified"), and counted on standard error: never silently rounded.
#include <iostream>

#include "commands.hpp"
#include "hinge/conformance/certified_line.hpp"
#include "hinge/io/jsonl.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge_stream.hpp"
#include "mesh_job.hpp"
#include "progress.hpp"

namespace hinge::tools {

namespace {

struct OracleOptions {
  std::string input, output;
  bool report_precision = false;
  unsigned start_bits = oracle::Options{}.start_bits;
  unsigned max_bits = oracle::Options{}.max_bits;
  MeshOptions mesh;
};

int run_hinges(const OracleOptions& o) {
  oracle::Options options;
  options.start_bits = o.start_bits;
  options.max_bits = o.max_bits;
  std::size_t flagged_hinges = 0, flagged_outputs = 0;
  const int status =
      run_hinge_stream(o.input, o.output, "oracle", [&](const std::string& id_json, const std::array<double, 12>& x) {
        const oracle::CertifiedTheta c = oracle::certified_theta_derivatives(x, options);
        if (!c.uncertified.empty()) {
          ++flagged_hinges;
          flagged_outputs += c.uncertified.size();
        }
        return conformance::certified_line(id_json, c, o.report_precision);
      });
  if (flagged_outputs > 0)
    std::cerr << "hinge oracle: " << flagged_outputs << " output(s) in " << flagged_hinges
              << " hinge(s) could not be certified within " << o.max_bits
              << " bits; they are flagged \"uncertified\" with their enclosures\n";
  return status;
}

// The certified energy, gradient and Hessian of a mesh; outputs not certified within --max-bits are listed
// on standard error (and printed as the double nearest to their enclosure's midpoint).
int run_mesh(const OracleOptions& o) {
  oracle::Options options;
  options.start_bits = o.start_bits;
  options.max_bits = o.max_bits;
  return run_mesh_command("oracle", [&] {
    const MeshJob job = load_mesh_job(o.mesh);
    oracle::CertifiedMesh m;
    Progress progress("hinge oracle: evaluations", static_cast<std::size_t>(o.mesh.repeat));
    for (int r = 0; r < o.mesh.repeat; ++r) {
      m = oracle::certified_mesh(job.deformed, job.rest ? *job.rest : job.deformed, job.topology, job.parameters,
                                 job.request, options);
      progress.update(static_cast<std::size_t>(r + 1));
    }
    for (const auto& u : m.uncertified)
      std::cerr << "hinge oracle: " << u.output << " not certified within " << o.max_bits << " bits: enclosure ["
                << u.lower << ", " << u.upper << "]\n";
    if (o.report_precision) std::cerr << "hinge oracle: bits " << m.bits << "\n";
    if (!m.uncertified.empty())
      std::cerr << "hinge oracle: " << m.uncertified.size() << " output(s) could not be certified within " << o.max_bits
                << " bits (listed above; printed as the double nearest to the enclosure's midpoint)\n";
    return write_mesh_outputs(o.mesh, m.rounded);
  });
}

}  // namespace

Action add_oracle(CLI::App& app) {
  auto* cmd = app.add_subcommand("oracle", "Certified correctly rounded values, for hinges or a whole mesh");
  auto o = std::make_shared<OracleOptions>();
  cmd->add_option("--input", o->input, "Input JSON Lines file (default: standard input)");
  cmd->add_option("--output", o->output, "Output JSON Lines file (default: standard output)");
  cmd->add_flag(
      "--report-precision", o->report_precision,
      "Add to each line \"path\" (\"fast\": the double-double fast path decided every output; \"exact\": "
      "the exact stage the rest; \"interval\": enclosures were needed), \"bits\" (working precision the "
      "enclosures needed, 0 if none), \"exact_bits\" (size of the largest exact integer, 0 if the exact stage "
      "did not run), \"ties\" (outputs exactly halfway between two doubles) and \"decided_exactly\" "
      "(outputs whose enclosure straddled a midpoint, rounded by an exact integer comparison)");
  cmd->add_option("--start-bits", o->start_bits, "First working precision of the certification (bits)")
      ->capture_default_str()
      ->check(CLI::Range(53u, 1u << 20));
  cmd->add_option("--max-bits", o->max_bits, "Precision cap of the certification (bits)")
      ->capture_default_str()
      ->check(CLI::Range(53u, 1u << 20));
  add_mesh_options(cmd, o->mesh, false);
  cmd->footer(
      "Every output is the double nearest to the exact value for the input doubles (ties to even), proved by a\n"
      "double-double evaluation with rigorous error bounds, or else exact integer arithmetic and MPFI enclosures\n"
      "(oracle/README.md). An output not certified within --max-bits\n"
      "bits is flagged on its line: \"uncertified\": [{\"output\", \"enclosure\": [lower, upper]}].\n"
      "With --mesh: the certified energy, gradient and Hessian of a mesh (options as for hinge hessian).");
  return [o]() -> int {
    if (!o->mesh.mesh.empty()) return run_mesh(*o);
    return run_hinges(*o);
  };
}

}  // namespace hinge::tools
