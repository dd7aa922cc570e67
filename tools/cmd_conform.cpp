// hinge conform: check another implementation against certified values (docs/contract.md; docs/conformance.md).
//   hinge conform --inputs [--output FILE]                       the conformance inputs {"id", "category", "x"}
//   hinge conform --candidate FILE [--json FILE] [--report F.html]  outputs in the hinge eval format, same ids
//   hinge conform --plugin LIB.so [--symbol NAME] [--save FILE]  a C function (hinge/candidate.h)
//   hinge conform --method M [--scalar S] [--save FILE]          one of hinge eval's methods, in process
//   hinge conform --mesh X.obj [--rest R.obj] --energy E --k K --hessian H.mtx [--gradient G.txt]
//   hinge conform --write-vectors DIR                            regenerate conformance/ (bit for bit)
// A bending term psi = k w f(theta, theta_bar) (docs/energy-conformance-cli.md): --energy E without --mesh,
//   E one of shells, tan, willmore, bridson, custom (the consistency checks only), with exactly one of
//   hinge conform --energy E [--weight W] [--k K] [--hessian-kind exact|gauss-newton] ...
//     --inputs [--output FILE]       the graded pairs {"id", "category", "x", "rest"}, then the consistency
//                                    probes (ids "consistency/<base id>/<n>", category "consistency")
//     --candidate FILE               lines {"id", "energy", "grad", "hess"} (or {"id", "error"}) for those ids;
//                                    without the probes' lines the consistency checks are not evaluated: FAIL
//     --plugin LIB.so [--symbol NAME] [--save FILE]   hinge_energy_candidate (hinge/candidate.h), on the pairs
//                                    and the probes, in a child process as for theta
//   with [--json FILE] [--report F.html] [--case-timeout S] [--verbose]; W one of contract, bridson,
//   edge-length, unit (quadratic: none); --depth deep adds the hard families' pairs (conditioning computed then).
// Exit status: 0 within the tolerance policy everywhere (and every consistency check passes), 1 not, 2 usage
// error, unreadable candidate or a plugin that cannot be loaded.
// The numerics (certified values, conditioning, policy, comparisons, consistency checks, report) are
// hinge::conformance's.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "commands.hpp"
#include "hinge/conformance/energy_report.hpp"
#include "hinge/conformance/html_report.hpp"
#include "hinge/conformance/plugin.hpp"
#include "hinge/conformance/report.hpp"
#include "hinge/conformance/sets.hpp"
#include "hinge/conformance/vectors.hpp"
#include "hinge/core/bending_problem.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/atomic_file.hpp"
#include "hinge/io/energy_lines.hpp"
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
  std::string output, candidate, plugin, save, write_vectors, method, scalar = "double";
  std::string symbol;  // --symbol; empty: hinge_candidate, or hinge_energy_candidate with --energy
  std::string json;    // --json FILE: the report as JSON
  std::string report;  // --report FILE.html: the report as a self-contained page
  std::string depth = "quick";
  std::vector<std::string> categories;
  conf::Policy policy;
  double case_timeout = 10;  // seconds, --plugin
  // mesh mode; --energy without --mesh: a bending term (weight and Hessian kind for it alone)
  std::string mesh, rest, energy, hessian, gradient;
  double k = 1;
  std::string weight = "contract", hessian_kind = "exact";
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

// One line per case: errors and tolerances (--verbose); `first` names the first output group (theta, energy).
void print_cases(std::ostream& out, const std::vector<conf::CaseOutcome>& outcomes, const char* first = "theta") {
  char line[512];
  std::snprintf(line, sizeof line, "%-44s %-4s %10s %10s %10s %10s %10s %10s\n", "case", "", first, "(tol)", "grad",
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

// The text report on standard output, the JSON and HTML reports if asked, the cases the plugin did not survive;
// the exit status.
int emit(const conf::Report& report, std::optional<io::AtomicFile>& json, std::optional<io::AtomicFile>& html,
         const std::vector<std::string>& not_survived) {
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

// The output files, opened before the candidate runs: one that cannot be written is a usage error.
void open_outputs(const ConformOptions& o, std::optional<io::AtomicFile>& saved, std::optional<io::AtomicFile>& json,
                  std::optional<io::AtomicFile>& html) {
  try {
    if (!o.save.empty()) saved.emplace(o.save);
    if (!o.json.empty()) json.emplace(o.json);
    if (!o.report.empty()) html.emplace(o.report);
  } catch (const std::runtime_error& e) {
    throw Unusable(e.what());
  }
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
      const std::string symbol = o.symbol.empty() ? "hinge_candidate" : o.symbol;
      plugin.emplace(o.plugin, symbol, o.case_timeout);
      name = "plugin " + o.plugin + " (" + symbol + ")";
    }
  } catch (const InputError& e) {
    throw Unusable(e.what());
  } catch (const conf::PluginError& e) {
    throw Unusable(e.what());
  }
  std::optional<io::AtomicFile> saved, json, html;
  open_outputs(o, saved, json, html);

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
  return emit(report, json, html, not_survived);
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

// --- A bending term (--energy without --mesh; docs/energy-conformance-cli.md) ---

// What the options name: the grading, its set, the consistency probes and their ids. A bad name is a usage error.
struct EnergyRun {
  conf::EnergyGrading grading;
  const conf::EnergySet* set = nullptr;
  conf::ConsistencyPlan plan;
  std::vector<std::string> probe_ids;
};

EnergyRun energy_run(const ConformOptions& o) {
  EnergyRun run;
  try {
    const std::vector<std::string>& weights = conf::weight_names();
    if (std::find(weights.begin(), weights.end(), o.weight) == weights.end()) {
      std::string choices;
      for (const std::string& w : weights) {
        if (!choices.empty()) choices += ", ";
        choices += w;
      }
      std::string why = "unknown weight \"";
      why += o.weight;
      why += "\" (choices: ";
      why += choices;
      why += ")";
      throw std::invalid_argument(why);
    }
    run.grading = conf::energy_grading(o.energy, o.weight, o.k, o.hessian_kind);
    run.set = run.grading.custom ? &conf::energy_set(run.grading.problem.model, conf::parse_depth(o.depth))
                                 : &conf::energy_set_of(run.grading.problem, conf::parse_depth(o.depth));
  } catch (const std::invalid_argument& e) {
    throw Unusable(e.what());
  }
  run.plan = conf::energy_consistency_plan(*run.set, conf::Dtype::float64);
  run.probe_ids = conf::consistency_probe_ids(run.plan);
  return run;
}

// --inputs: the graded pairs (none for custom), then the consistency probes.
int write_energy_inputs(const ConformOptions& o, const EnergyRun& run) {
  std::optional<io::AtomicFile> file;
  std::ostream* out = &std::cout;
  if (!o.output.empty() && o.output != "-") out = &file.emplace(o.output).stream();
  if (!run.grading.custom)
    for (const conf::EnergyCase& c : run.set->cases)
      *out << io::energy_input_line(c.id, c.category, c.x, c.rest) << '\n';
  for (std::size_t p = 0; p < run.plan.x.size(); ++p)
    *out << io::energy_input_line(run.probe_ids[p], conf::consistency_category, run.plan.x[p], run.plan.rest[p])
         << '\n';
  out->flush();
  if (file) file->commit();
  return *out ? exit_done : exit_invalid_input;
}

// --candidate or --plugin: the candidate on the graded pairs and the probes, graded by conf::grade_energy.
int run_energy(const ConformOptions& o) {
  const EnergyRun run = energy_run(o);
  if (o.inputs) return write_energy_inputs(o, run);
  std::optional<conf::Plugin> plugin;
  std::map<std::string, io::EnergyOutput> file;
  std::string name;
  try {
    if (!o.candidate.empty()) {
      file = io::read_energy_outputs(o.candidate);
      name = "candidate " + o.candidate;
    } else {
      const std::string symbol = o.symbol.empty() ? "hinge_energy_candidate" : o.symbol;
      plugin.emplace(o.plugin, symbol, o.case_timeout, conf::PluginKind::energy);
      name = "plugin " + o.plugin + " (" + symbol + ")";
    }
  } catch (const InputError& e) {
    throw Unusable(e.what());
  } catch (const conf::PluginError& e) {
    throw Unusable(e.what());
  }
  std::optional<io::AtomicFile> saved, json, html;
  open_outputs(o, saved, json, html);

  const std::vector<conf::EnergyCase>& cases = run.set->cases;
  const std::size_t total = (run.grading.custom ? 0 : cases.size()) + run.plan.x.size();
  std::vector<std::string> not_survived;  // cases on which the plugin crashed or timed out
  std::size_t done = 0, found = 0;
  Progress progress("hinge conform: cases and probes", total);
  const auto evaluate = [&](const std::string& id, const std::array<double, 12>& x,
                            const std::array<double, 12>& rest) {
    conf::CandidateResult r;
    if (plugin) {
      r = (*plugin)(x, rest);
      if (conf::Plugin::fatal(r)) not_survived.push_back(id + ": " + r.error);
    } else if (auto it = file.find(id); it != file.end()) {
      r = it->second;
      ++found;
    }
    if (saved) saved->stream() << io::energy_output_line(id, r) << '\n';
    progress.update(++done);
    return r;
  };
  std::vector<conf::CandidateResult> results;
  if (!run.grading.custom)
    for (const conf::EnergyCase& c : cases) results.push_back(evaluate(c.id, c.x, c.rest));
  const std::size_t pairs_found = found;
  std::vector<conf::EnergyOutputs> probes;
  for (std::size_t p = 0; p < run.plan.x.size(); ++p)
    probes.push_back(conf::probe_outputs(evaluate(run.probe_ids[p], run.plan.x[p], run.plan.rest[p])));
  if (saved) saved->commit();

  std::vector<std::string> notes;
  if (!o.candidate.empty()) {
    const std::size_t probes_found = found - pairs_found, m = run.plan.x.size();
    if (probes_found == 0)
      notes.push_back("the candidate file has no line for the " + std::to_string(m) +
                      " consistency probes (ids consistency/<base id>/<n>, written by --inputs): the consistency "
                      "checks were not evaluated, and fail");
    else if (probes_found < m)
      notes.push_back(std::to_string(m - probes_found) + " of the " + std::to_string(m) +
                      " consistency probes have no line in the candidate file: the checks that need them were not "
                      "evaluated, and fail");
    if (file.size() > found)
      std::cerr << "hinge conform: " << file.size() - found
                << " line(s) of the candidate have ids that are neither graded pairs nor probes (ignored)\n";
  }
  conf::Grading grading;
  grading.policy = o.policy;
  conf::Report report = conf::grade_energy(name, *run.set, run.grading, grading, {}, std::move(results), probes);
  report.notes.insert(report.notes.begin(), notes.begin(), notes.end());
  if (o.verbose) print_cases(std::cout, report.outcomes, "energy");
  return emit(report, json, html, not_survived);
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
  cmd->add_option("--symbol", o->symbol,
                  "The plugin's function (default hinge_candidate; with --energy, hinge_energy_candidate)");
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
  cmd->add_option("--energy", o->energy,
                  "Mesh mode: tan, shells, willmore or bridson. Without --mesh, with --inputs, --candidate or\n"
                  "--plugin: the bending term psi = k w f(theta, theta_bar) to grade (shells, tan, willmore, bridson,\n"
                  "or custom: the consistency checks only; docs/energy-conformance-cli.md)");
  cmd->add_option("--k", o->k, "Mesh mode and --energy: bending stiffness")->capture_default_str();
  auto* weight = cmd->add_option("--weight", o->weight,
                                 "With --energy: the weight w of each hinge (contract: 3 |e_bar|^2 / A_bar, bridson,\n"
                                 "edge-length, unit)")
                     ->capture_default_str();
  auto* hessian_kind = cmd->add_option("--hessian-kind", o->hessian_kind,
                                       "With --energy: the Hessian the candidate gives, exact or gauss-newton\n"
                                       "(c f'' grad theta grad theta^T)")
                           ->capture_default_str();
  cmd->add_option("--hessian", o->hessian, "Mesh mode: the candidate's energy Hessian (Matrix Market)");
  cmd->add_option("--gradient", o->gradient, "Mesh mode: the candidate's energy gradient (3n numbers)");
  cmd->footer(
      "Reports, per category, the median and worst normwise error of theta, grad and hess in units of 2^-53,\n"
      "the worst case (largest error / tolerance), missing and non-finite results. A case passes when each\n"
      "output's error is at most base + c kappa (docs/conformance.md), and the tier each category reaches:\n"
      "correctly-rounded, faithful (<= 1 unit), 4u (<= 4 units), policy, approximate (outside the policy but\n"
      "within 2^-20 (1 + kappa) relative: the formula looks right and is not accurate), fail. A failing category\n"
      "is diagnosed: the usual convention mismatches (sign, degrees, unsigned angle, vertex order, Hessian\n"
      "triangle, ...) that explain it are named with what to change. --energy E (without --mesh) grades a bending\n"
      "term instead: hinge_energy_candidate plugins, or files {\"id\", \"energy\", \"grad\", \"hess\"} answering\n"
      "--inputs (its graded pairs and consistency probes), with consistency checks (docs/energy-conformance-cli.md).\n"
      "Exit: 0 pass, 1 fail (approximate included), 2 usage error or unreadable candidate.");
  return [o, weight, hessian_kind]() -> int {
    if (!o->energy.empty() && o->mesh.empty()) {  // a bending term
      const int energy_modes = int(o->inputs) + int(!o->candidate.empty()) + int(!o->plugin.empty());
      const char* problem =
          !o->method.empty() || !o->write_vectors.empty()
              ? "--energy (without --mesh) goes with --inputs, --candidate or --plugin, not --method or --write-vectors"
          : energy_modes != 1      ? "--energy (without --mesh) needs exactly one of --inputs, --candidate, --plugin"
          : !o->categories.empty() ? "--category does not go with --energy"
          : !o->save.empty() && o->plugin.empty() ? "--save goes with --plugin"
          : (!o->json.empty() || !o->report.empty()) && o->inputs
              ? "--json and --report go with --candidate or --plugin"
          : !o->output.empty() && !o->inputs ? "--output goes with --inputs"
                                             : nullptr;
      if (problem) {
        std::cerr << "hinge conform: " << problem << "\n";
        return exit_usage;
      }
      try {
        return run_energy(*o);
      } catch (const Unusable& e) {
        std::cerr << "hinge conform: " << e.what() << "\n";
        return exit_usage;
      } catch (const std::runtime_error& e) {  // output files (io::AtomicFile), filesystem errors
        std::cerr << "hinge conform: " << e.what() << "\n";
        return exit_invalid_input;
      }
    }
    if (weight->count() > 0 || hessian_kind->count() > 0) {
      std::cerr << "hinge conform: --weight and --hessian-kind go with --energy (without --mesh)\n";
      return exit_usage;
    }
    const int modes = int(o->inputs) + int(!o->candidate.empty()) + int(!o->plugin.empty()) + int(!o->method.empty()) +
                      int(!o->write_vectors.empty()) + int(!o->mesh.empty());
    if (modes != 1) {
      std::cerr
          << "hinge conform: give exactly one of --inputs, --candidate, --plugin, --method, --mesh, --write-vectors\n"
             "(and --energy E for a bending term)\n";
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
