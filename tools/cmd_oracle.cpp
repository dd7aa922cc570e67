// hinge oracle [--input FILE] [--output FILE] [--report-precision] [--max-bits N]   hinges as JSON Lines
// hinge oracle --mesh X.obj ... (options of hinge hessian)                           a whole mesh
// Certified: every output is the double nearest to the exact value for the input doubles
// (hinge/oracle/oracle.hpp, oracle/README.md). An output that cannot be certified within --max-bits is
// printed as the double nearest to its enclosure's midpoint and flagged on its line with the enclosure
// ("uncertified"), and counted on standard error: never silently rounded.
#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "hinge/oracle/mesh.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge_stream.hpp"
#include "jsonl.hpp"
#include "mesh_job.hpp"

namespace hinge::tools {

namespace {

struct OracleOptions {
  std::string input, output;
  bool report_precision = false;
  unsigned start_bits = oracle::Options{}.start_bits;
  unsigned max_bits = oracle::Options{}.max_bits;
  MeshOptions mesh;
};

// The result line of hinge eval, with the oracle's extra fields before the closing brace.
std::string certified_line(const std::string& id_json, const oracle::CertifiedTheta& c, bool report_precision) {
  reference::RoundedTheta r;
  r.theta = c.theta;
  r.grad = c.grad;
  r.hess = c.hess;
  std::string line = result_line(id_json, r);
  line.pop_back();  // '}'
  if (report_precision)
    line += ", \"bits\": " + std::to_string(c.bits) + ", \"exact_bits\": " + std::to_string(c.exact_bits) +
            ", \"ties\": " + std::to_string(c.ties) + ", \"decided_exactly\": " + std::to_string(c.decided_exactly);
  if (!c.uncertified.empty()) {
    nlohmann::json flags = nlohmann::json::array();
    for (const auto& u : c.uncertified)
      flags.push_back({{"output", u.output}, {"enclosure", {u.lower, u.upper}}});
    line += ", \"uncertified\": " + flags.dump();
  }
  line += '}';
  return line;
}

int run_hinges(const OracleOptions& o) {
  oracle::Options options;
  options.start_bits = o.start_bits;
  options.max_bits = o.max_bits;
  std::size_t flagged_hinges = 0, flagged_outputs = 0;
  const int status = run_hinge_stream(
      o.input, o.output,
      [&](const std::string& id_json, const std::array<double, 12>& x) {
        const oracle::CertifiedTheta c = oracle::certified_theta_derivatives(x, options);
        if (!c.uncertified.empty()) {
          ++flagged_hinges;
          flagged_outputs += c.uncertified.size();
        }
        return certified_line(id_json, c, o.report_precision);
      },
      "oracle");
  if (flagged_outputs > 0)
    std::cerr << "hinge oracle: " << flagged_outputs << " output(s) in " << flagged_hinges
              << " hinge(s) could not be certified within " << o.max_bits
              << " bits; they are flagged \"uncertified\" with their enclosures\n";
  return status;
}

}  // namespace

Action add_oracle(CLI::App& app) {
  auto* cmd = app.add_subcommand("oracle", "Certified correctly rounded values, for hinges or a whole mesh");
  auto o = std::make_shared<OracleOptions>();
  cmd->add_option("--input", o->input, "Input JSON Lines file (default: standard input)");
  cmd->add_option("--output", o->output, "Output JSON Lines file (default: standard output)");
  cmd->add_flag("--report-precision", o->report_precision,
                "Add to each line \"bits\" (working precision the certification needed), \"exact_bits\" (size of "
                "the largest exact integer), \"ties\" (outputs exactly halfway between two doubles) and \"decided_exactly\" "
                "(outputs whose enclosure straddled a midpoint, rounded by an exact integer comparison)");
  cmd->add_option("--start-bits", o->start_bits, "First working precision of the certification (bits)")
      ->capture_default_str()
      ->check(CLI::Range(53u, 1u << 20));
  cmd->add_option("--max-bits", o->max_bits, "Precision cap of the certification (bits)")
      ->capture_default_str()
      ->check(CLI::Range(53u, 1u << 20));
  add_mesh_options(cmd, o->mesh, false);
  cmd->footer(
      "Every output is the double nearest to the exact value for the input doubles (ties to even), proved by\n"
      "exact integer arithmetic and MPFI enclosures (oracle/README.md). An output not certified within --max-bits\n"
      "bits is flagged on its line: \"uncertified\": [{\"output\", \"enclosure\": [lower, upper]}].\n"
      "With --mesh: the certified energy, gradient and Hessian of a mesh (options as for hinge hessian).");
  return [o]() -> int {
    if (!o->mesh.mesh.empty()) {
      oracle::Options options;
      options.start_bits = o->start_bits;
      options.max_bits = o->max_bits;
      std::size_t flagged = 0;
      unsigned bits = 0;
      const int status = run_mesh_job(
          o->mesh,
          [&](const MeshJob& job) {
            oracle::CertifiedMesh m = oracle::certified_mesh(*job.deformed, *job.rest, *job.topology, job.parameters,
                                                             job.request, options);
            flagged = m.uncertified.size();
            bits = m.bits;
            for (const auto& u : m.uncertified)
              std::cerr << "hinge oracle: " << u.output << " not certified within " << o->max_bits
                        << " bits: enclosure [" << u.lower << ", " << u.upper << "]\n";
            return std::move(m.rounded);
          },
          "oracle");
      if (o->report_precision) std::cerr << "hinge oracle: bits " << bits << "\n";
      if (flagged > 0)
        std::cerr << "hinge oracle: " << flagged << " output(s) could not be certified within " << o->max_bits
                  << " bits (listed above; printed as the double nearest to the enclosure's midpoint)\n";
      return status;
    }
    return run_hinges(*o);
  };
}

}  // namespace hinge::tools
