// hinge conform: check another implementation against certified values (docs/contract.md; docs/conformance.md).
//   hinge conform --inputs [--output FILE]                       the conformance inputs {"id", "category", "x"}
//   hinge conform --candidate FILE [--json FILE] [--report F.html]  outputs in the hinge eval format, same ids
//   hinge conform --plugin LIB.so [--symbol NAME] [--save FILE]  a C function (hinge/candidate.h)
//   hinge conform --method M [--scalar S] [--save FILE]          one of hinge eval's methods, in process
//   hinge conform --mesh X.obj [--rest R.obj] --energy E --k K --hessian H.mtx [--gradient G.txt]
//   hinge conform --write-vectors DIR                            regenerate conformance/ (bit for bit)
// Exit status: 0 within the tolerance policy everywhere, 1 not, 2 usage error or unreadable candidate.
// The numerics (certified values, conditioning, policy, comparisons, report) are hinge::conformance's.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "commands.hpp"
#include "hinge/conformance/html_report.hpp"
#include "hinge/conformance/plugin.hpp"
#include "hinge/conformance/report.hpp"
#include "hinge/conformance/sets.hpp"
#include "hinge/conformance/vectors.hpp"
#include "hinge/core/bending_problem.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/atomic_file.hpp"
#include "hinge/io/eval_output.hpp"
#include "hinge/io/jsonl.hpp"
#include "hinge/io/matrix_market.hpp"
#include "hinge/io/number.hpp"
#include "hinge/io/obj.hpp"
#include "hinge/methods/methods.hpp"
#include "progress.hpp"

namespace hinge::tools {

namespace {

namespace conf = conformance;

struct ConformOptions {
  bool inputs = false, verbose = false;
  std::string output, candidate, plugin, symbol = "hinge_candidate", save, write_vectors, method, scalar = "double";
  std::string json;    // --json FILE: the report as JSON
  std::string report;  // --report FILE.html: the report as a self-contained page
  std::string depth = "quick";
  std::vector<std::string> categories;
  conf::Policy policy;
  double case_timeout = 10;  // seconds, --plugin
  // mesh mode
  std::string mesh, rest, energy, hessian, gradient;
  double k = 1;
};

// A usage error or an unreadable candidate: exit status 2.
struct Unusable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The committed set's cases with their expected values (--depth), those of the chosen categories.
std::vector<conf::Expected> selected_expected(const ConformOptions& o) {
  const conf::Depth depth = conf::parse_depth(o.depth);  // std::invalid_argument: usage
  const std::vector<std::string> known = conf::set_categories(conf::Dtype::float64, depth);
  for (const auto& c : o.categories)
    if (std::find(known.begin(), known.end(), c) == known.end())
      throw std::invalid_argument("unknown category '" + c + "'");
  std::vector<conf::Expected> some;
  for (const conf::Expected& e : conf::conformance_set(conf::Dtype::float64, depth))
    if (o.categories.empty() ||
        std::find(o.categories.begin(), o.categories.end(), e.input.category) != o.categories.end())
      some.push_back(e);
  return some;
}

// One line per case: errors and tolerances (--verbose).
void print_cases(std::ostream& out, const std::vector<conf::CaseOutcome>& outcomes) {
  char line[512];
  std::snprintf(line, sizeof line, "%-44s %-4s %10s %10s %10s %10s %10s %10s\n", "case", "", "theta", "(tol)", "grad",
                "(tol)", "hess", "(tol)");
  out << line;
  for (const auto& o : outcomes) {
    std::snprintf(line, sizeof line, "%-44s %-4s %10.3g %10.3g %10.3g %10.3g %10.3g %10.3g\n", o.id.c_str(),
                  o.pass ? "ok" : "FAIL", o.error[0], o.tolerance[0], o.error[1], o.tolerance[1], o.error[2],
                  o.tolerance[2]);
    out << line;
  }
  out << '\n';
}

// One of our own methods as a candidate: its results rounded to double, an error line where it cannot
// evaluate a hinge (what `hinge eval` would print).
conf::CandidateResult method_result(methods::Method method, const ScalarType& scalar, const std::array<double, 12>& x) {
  conf::CandidateResult r;
  try {
    const RoundedTheta t = methods::evaluate_hinge(method, scalar, x);
    r.status = conf::CandidateResult::Status::ok;
    r.theta = t.theta;
    r.grad = t.grad;
    r.hess = t.hess;
    io::check_finite(r);
  } catch (const InputError& e) {
    r.status = conf::CandidateResult::Status::error;
    r.error = e.what();
  } catch (const DomainError& e) {
    r.status = conf::CandidateResult::Status::error;
    r.error = e.what();
  }
  return r;
}

int run_cases(const ConformOptions& o) {
  std::optional<conf::Plugin> plugin;
  std::optional<std::pair<methods::Method, ScalarType>> method;
  std::map<std::string, conf::CandidateResult> file;
  std::string name;
  try {
    if (!o.candidate.empty()) {
      file = io::read_eval_outputs(o.candidate);
      name = "candidate " + o.candidate;
    } else if (!o.method.empty()) {
      method.emplace(methods::parse_method(o.method), parse_scalar_type(o.scalar));  // std::invalid_argument: usage
      name = "hinge eval --method " + o.method + " --scalar " + o.scalar;
    } else {
      plugin.emplace(o.plugin, o.symbol, o.case_timeout);
      name = "plugin " + o.plugin + " (" + o.symbol + ")";
    }
  } catch (const InputError& e) {
    throw Unusable(e.what());
  } catch (const conf::PluginError& e) {
    throw Unusable(e.what());
  }
  std::optional<io::AtomicFile> saved, json, html;
  try {  // an output that cannot be written is a usage error, found before the candidate runs
    if (!o.save.empty()) saved.emplace(o.save);
    if (!o.json.empty()) json.emplace(o.json);
    if (!o.report.empty()) html.emplace(o.report);
  } catch (const std::runtime_error& e) {
    throw Unusable(e.what());
  }

  std::vector<conf::Expected> cases = selected_expected(o);
  std::vector<conf::CandidateResult> results;
  std::vector<std::string> not_survived;  // cases on which the plugin crashed or timed out
  Progress progress("hinge conform: cases", cases.size());
  std::size_t unknown = file.size();
  for (const conf::Expected& e : cases) {
    const conf::Case& c = e.input;
    conf::CandidateResult r;
    if (plugin) {
      r = (*plugin)(c.x);
      if (conf::Plugin::fatal(r)) not_survived.push_back(c.id + ": " + r.error);
    } else if (method) {
      r = method_result(method->first, method->second, c.x);
    } else if (auto it = file.find(c.id); it != file.end()) {
      r = it->second;
      --unknown;
    }
    if (saved) saved->stream() << io::eval_output_line(c.id, r) << '\n';
    results.push_back(std::move(r));
    progress.update(results.size());
  }
  if (saved) saved->commit();
  if (!o.candidate.empty() && unknown > 0 && o.categories.empty())
    std::cerr << "hinge conform: " << unknown
              << " line(s) of the candidate have ids that are not conformance cases (ignored)\n";
  conf::Grading grading;
  grading.policy = o.policy;
  const conf::Report report =
      conf::make_report(name, std::move(cases), std::move(results), grading, conf::contract_stencil, o.depth);
  if (o.verbose) print_cases(std::cout, report.outcomes);
  conf::print_report(std::cout, report);
  if (json) {
    conf::write_json_report(json->stream(), report);
    json->commit();
  }
  if (html) {
    conf::write_html_report(html->stream(), report);
    html->commit();
  }
  if (!not_survived.empty()) {
    std::cout << "\nthe plugin did not survive " << not_survived.size()
              << " case(s) (each failed; its process was started again):\n";
    for (const auto& line : not_survived) std::cout << "  " << line << "\n";
  }
  return report.passed && not_survived.empty() ? exit_done : exit_invalid_input;
}

int write_inputs(const ConformOptions& o) {
  std::optional<io::AtomicFile> file;
  std::ostream* out = &std::cout;
  if (!o.output.empty() && o.output != "-") out = &file.emplace(o.output).stream();
  for (const conf::Expected& e : selected_expected(o))
    *out << io::input_line(e.input.id, e.input.category, e.input.x) << '\n';
  out->flush();
  if (file) file->commit();
  return *out ? exit_done : exit_invalid_input;
}

void print_mesh_comparison(const char* what, const conf::MeshComparison& c) {
  std::cout << what << "normwise error " << c.error << " units of 2^-53, tolerance " << c.tolerance << " = "
            << conf::mesh_base << " kappa_sum (kappa_sum " << c.kappa_sum << ")\n";
}

int run_mesh(const ConformOptions& o) {
  if (o.hessian.empty()) throw std::invalid_argument("--mesh needs --hessian H.mtx (the candidate's Hessian)");
  if (o.energy.empty()) throw std::invalid_argument("--mesh needs --energy (tan, shells, willmore, bridson)");
  const EnergyParameters parameters = bending_problem({o.k, "--k"}, o.energy, "--energy").parameters();
  Mesh deformed, rest;
  Topology topology;
  deformed = io::read_obj(o.mesh);  // hinge::InputError: exit status 1, as for every command that reads a mesh
  rest = o.rest.empty() ? deformed : io::read_obj(o.rest);
  topology = build_topology(deformed);
  check_bending_mesh(topology, deformed, o.rest.empty() ? nullptr : &rest, {o.mesh, o.rest, "", false});
  const oracle::CertifiedMesh m = oracle::certified_mesh(deformed, rest, topology, parameters, want_all);
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(topology.vertex_count);
  Eigen::SparseMatrix<double> hessian;
  std::optional<std::vector<double>> gradient;
  try {
    hessian = io::read_matrix_market(o.hessian, n);
    if (!o.gradient.empty()) {
      gradient = io::read_numbers(o.gradient);
      if (static_cast<Eigen::Index>(gradient->size()) != n)
        throw InputError(o.gradient + ": expected " + std::to_string(n) + " numbers");
    }
  } catch (const InputError& e) {
    throw Unusable(e.what());
  }
  std::cout << "hinge conform: mesh " << o.mesh << " (" << topology.hinges.size() << " hinges, energy " << o.energy
            << ", k " << io::format_double(o.k) << "), certified against the candidate's files\n";
  const conf::MeshComparison h = conf::compare_mesh_hessian(m, hessian);
  print_mesh_comparison("Hessian:  ", h);
  bool pass = h.pass;
  if (gradient) {
    const conf::MeshComparison g = conf::compare_mesh_gradient(m, *gradient);
    print_mesh_comparison("gradient: ", g);
    pass = pass && g.pass;
  }
  std::cout << (pass ? "PASS\n" : "FAIL (exit status 1)\n");
  return pass ? exit_done : exit_invalid_input;
}

int write_vectors(const ConformOptions& o) {
  std::optional<Progress> progress;
  const conf::VectorsSummary s = conf::write_vectors(o.write_vectors, [&](std::size_t done, std::size_t total) {
    if (!progress) progress.emplace("hinge conform: vectors", total);
    progress->update(done);
  });
  std::cerr << "hinge conform: wrote under " << o.write_vectors << ": " << s.quick << " hinge cases (hinges/), "
            << s.float32 << " (hinges-float32/), " << s.deep << " (deep/: " << s.deep_draws << " draws, "
            << s.deep_invalid << " invalid, " << s.deep_uncertified << " uncertified dropped), " << s.deep_float32
            << " (deep-float32/: " << s.deep_float32_draws << " draws, " << s.deep_float32_invalid << " invalid, "
            << s.deep_float32_uncertified << " uncertified dropped), " << s.energy_cases
            << " energy cases' conditioning (energies/), " << s.meshes << " mesh cases\n";
  return exit_done;
}

}  // namespace

int conform_method(const std::string& method, const std::string& scalar) {
  ConformOptions o;
  o.method = method;
  o.scalar = scalar;
  return run_cases(o);
}

Action add_conform(CLI::App& app) {
  auto* cmd = app.add_subcommand("conform", "Check another implementation against certified values");
  auto o = std::make_shared<ConformOptions>();
  cmd->add_flag("--inputs", o->inputs, "Write the conformance inputs as JSON Lines {\"id\", \"category\", \"x\"}");
  cmd->add_option("--output", o->output, "With --inputs: write here (default: standard output)");
  cmd->add_option("--candidate", o->candidate, "Check outputs in the hinge eval format (same ids as --inputs)");
  cmd->add_option("--plugin", o->plugin, "Check a shared library exporting the C function of hinge/candidate.h");
  cmd->add_option("--symbol", o->symbol, "The plugin's function")->capture_default_str();
  cmd->add_option("--case-timeout", o->case_timeout,
                  "With --plugin: seconds a case may take (the plugin runs in a child process: a crash or a time-out\n"
                  "fails that case, and the others still run)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--method", o->method, "Check one of hinge eval's methods: reference, fast, autodiff, symbolic");
  cmd->add_option("--scalar", o->scalar, "With --method: its scalar type")->capture_default_str();
  cmd->add_option("--save", o->save, "With --plugin or --method: also write its outputs in the hinge eval format");
  cmd->add_option("--json", o->json,
                  "With --candidate, --plugin or --method: also write the report as JSON here "
                  "(per category and per case: errors, tolerances, kappa, tier)");
  cmd->add_option(
      "--report", o->report,
      "With --candidate, --plugin or --method: also write the report as one self-contained HTML page\n"
      "(tiers, the diagnosis, error against condition number, the worst case's Hessian errors, a reproducer)");
  cmd->add_option("--depth", o->depth,
                  "quick (the conformance set) or deep (and at least 1000 more hinges of the hard families)")
      ->capture_default_str();
  cmd->add_option("--category", o->categories, "Only these categories (repeatable)");
  cmd->add_flag("--verbose", o->verbose, "Also print every case's errors and tolerances");
  cmd->add_option("--tolerance-base", o->policy.base, "Tolerance policy: units of 2^-53 granted to every case")
      ->capture_default_str();
  cmd->add_option("--tolerance-c", o->policy.c, "Tolerance policy: multiple of kappa")->capture_default_str();
  cmd->add_option("--write-vectors", o->write_vectors, "Regenerate the conformance vectors (conformance/) in DIR");
  cmd->add_option("--mesh", o->mesh, "Mesh mode: the deformed mesh (OBJ)");
  cmd->add_option("--rest", o->rest, "Mesh mode: the rest mesh (default: the deformed mesh)");
  cmd->add_option("--energy", o->energy, "Mesh mode: tan, shells, willmore or bridson");
  cmd->add_option("--k", o->k, "Mesh mode: bending stiffness")->capture_default_str();
  cmd->add_option("--hessian", o->hessian, "Mesh mode: the candidate's energy Hessian (Matrix Market)");
  cmd->add_option("--gradient", o->gradient, "Mesh mode: the candidate's energy gradient (3n numbers)");
  cmd->footer(
      "Reports, per category, the median and worst normwise error of theta, grad and hess in units of 2^-53,\n"
      "the worst case (largest error / tolerance), missing and non-finite results. A case passes when each\n"
      "output's error is at most base + c kappa (docs/conformance.md), and the tier each category reaches:\n"
      "correctly-rounded, faithful (<= 1 unit), 4u (<= 4 units), policy, approximate (outside the policy but\n"
      "within 2^-20 (1 + kappa) relative: the formula looks right and is not accurate), fail. A failing category\n"
      "is diagnosed: the usual convention mismatches (sign, degrees, unsigned angle, vertex order, Hessian\n"
      "triangle, ...) that explain it are named with what to change. Exit: 0 pass, 1 fail (approximate\n"
      "included), 2 usage error or unreadable candidate.");
  return [o]() -> int {
    const int modes = int(o->inputs) + int(!o->candidate.empty()) + int(!o->plugin.empty()) + int(!o->method.empty()) +
                      int(!o->write_vectors.empty()) + int(!o->mesh.empty());
    if (modes != 1) {
      std::cerr
          << "hinge conform: give exactly one of --inputs, --candidate, --plugin, --method, --mesh, --write-vectors\n";
      return exit_usage;
    }
    if (!o->save.empty() && o->plugin.empty() && o->method.empty()) {
      std::cerr << "hinge conform: --save goes with --plugin or --method\n";
      return exit_usage;
    }
    if ((!o->json.empty() || !o->report.empty()) && o->candidate.empty() && o->plugin.empty() && o->method.empty()) {
      std::cerr << "hinge conform: --json and --report go with --candidate, --plugin or --method\n";
      return exit_usage;
    }
    try {
      if (o->inputs) return write_inputs(*o);
      if (!o->write_vectors.empty()) return write_vectors(*o);
      if (!o->mesh.empty()) return run_mesh(*o);
      return run_cases(*o);
    } catch (const Unusable& e) {
      std::cerr << "hinge conform: " << e.what() << "\n";
      return exit_usage;
    } catch (const InputError& e) {
      std::cerr << "hinge conform: " << e.what() << "\n";
      return exit_invalid_input;
    } catch (const DomainError& e) {
      std::cerr << "hinge conform: " << e.what() << "\n";
      return exit_invalid_input;
    } catch (const std::runtime_error& e) {  // output files (io::AtomicFile), filesystem errors
      std::cerr << "hinge conform: " << e.what() << "\n";
      return exit_invalid_input;
    }
  };
}

}  // namespace hinge::tools
