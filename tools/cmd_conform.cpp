// hinge conform: check another implementation against certified values (CONVENTIONS.md; docs/conformance.md).
//   hinge conform --inputs [--output FILE]                       the conformance inputs {"id", "category", "x"}
//   hinge conform --candidate FILE                               outputs in the hinge eval format, same ids
//   hinge conform --plugin LIB.so [--symbol NAME] [--save FILE]  a C function (hinge/candidate.h)
//   hinge conform --mesh X.obj [--rest R.obj] --energy E --k K --hessian H.mtx [--gradient G.txt]
//   hinge conform --write-vectors DIR                            regenerate conformance/ (bit for bit)
// Exit status: 0 within the tolerance policy everywhere, 1 not, 2 usage error or unreadable candidate.
// The numerics (certified values, conditioning, policy, report) are in hinge::oracle::conformance.
#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "hinge/candidate.h"
#include "hinge/oracle/conformance.hpp"
#include "hinge/reference/errors.hpp"
#include "hinge/reference/obj.hpp"
#include "jsonl.hpp"
#include "output.hpp"
#include "progress.hpp"

namespace hinge::tools {

namespace {

namespace conf = oracle::conformance;
using Status = conf::CandidateResult::Status;

struct ConformOptions {
  bool inputs = false, verbose = false;
  std::string output, candidate, plugin, symbol = "hinge_candidate", save, write_vectors;
  std::vector<std::string> categories;
  conf::Policy policy;
  // mesh mode
  std::string mesh, rest, energy, hessian, gradient;
  double k = 1;
};

// A usage error or an unreadable candidate: exit status 2.
struct Unusable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string json_string(const std::string& s) { return nlohmann::json(s).dump(); }

void append_array(std::string& out, const double* v, std::size_t n) {
  out += '[';
  for (std::size_t i = 0; i < n; ++i) {
    if (i) out += ", ";
    append_double(out, v[i]);
  }
  out += ']';
}

std::vector<conf::Case> selected_inputs(const ConformOptions& o) {
  std::vector<conf::Case> all = conf::inputs();
  if (o.categories.empty()) return all;
  for (const auto& c : o.categories)
    if (std::find(conf::categories().begin(), conf::categories().end(), c) == conf::categories().end())
      throw std::invalid_argument("unknown category '" + c + "'");
  std::vector<conf::Case> some;
  for (auto& c : all)
    if (std::find(o.categories.begin(), o.categories.end(), c.category) != o.categories.end()) some.push_back(c);
  return some;
}

// The output of one candidate file line.
conf::CandidateResult parse_result(const nlohmann::json& j) {
  conf::CandidateResult r;
  if (auto e = j.find("error"); e != j.end()) {
    r.status = Status::error;
    r.error = e->is_string() ? e->get<std::string>() : e->dump();
    return r;
  }
  auto number = [&r](const nlohmann::json& v, double& out) {
    if (v.is_number()) out = v.get<double>();
    else r.status = Status::nonfinite;  // null, "NaN", ...
  };
  auto array = [&](const char* name, double* out, std::size_t n) {
    auto a = j.find(name);
    if (a == j.end() || !a->is_array() || a->size() != n) {
      r.status = Status::missing;
      r.error = std::string("no \"") + name + "\" array of " + std::to_string(n);
      return false;
    }
    for (std::size_t i = 0; i < n; ++i) number((*a)[i], out[i]);
    return true;
  };
  r.status = Status::ok;
  auto t = j.find("theta");
  if (t == j.end()) {
    r.status = Status::missing;
    r.error = "no \"theta\"";
    return r;
  }
  number(*t, r.theta);
  if (!array("grad", r.grad.data(), 12) || !array("hess", r.hess.data(), 144)) return r;
  conf::check_finite(r);
  return r;
}

// In a line that is not valid JSON, the string value of its first "id" key, quotes and escapes
// included ("id" : "..."), or nothing. (A hand scan: std::regex trips GCC 12's -Wmaybe-uninitialized
// under the sanitizers.)
std::optional<std::string> quoted_id(const std::string& text) {
  auto skip_space = [&](std::size_t i) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    return i;
  };
  for (std::size_t at = text.find("\"id\""); at != std::string::npos; at = text.find("\"id\"", at + 1)) {
    std::size_t i = skip_space(at + 4);
    if (i >= text.size() || text[i] != ':') continue;
    i = skip_space(i + 1);
    if (i >= text.size() || text[i] != '"') continue;
    for (std::size_t j = i + 1; j < text.size(); ++j) {
      if (text[j] == '\\') ++j;
      else if (text[j] == '"') return text.substr(i, j - i + 1);
    }
    return std::nullopt;
  }
  return std::nullopt;
}

// The candidate file: results by id. Lines that are not JSON (a "NaN" in them, say) count as non-finite
// when their id can be found; otherwise the file is unreadable.
std::map<std::string, conf::CandidateResult> read_candidate(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Unusable("cannot read candidate " + path);
  std::map<std::string, conf::CandidateResult> results;
  std::string text;
  for (long number = 1; std::getline(in, text); ++number) {
    if (blank(text)) continue;
    std::string id;
    conf::CandidateResult r;
    try {
      const nlohmann::json j = nlohmann::json::parse(text);
      if (!j.is_object() || !j.contains("id") || !j["id"].is_string())
        throw Unusable(path + ":" + std::to_string(number) + ": not an object with a string \"id\"");
      id = j["id"].get<std::string>();
      r = parse_result(j);
    } catch (const nlohmann::json::exception&) {
      const std::optional<std::string> quoted = quoted_id(text);
      if (!quoted)
        throw Unusable(path + ":" + std::to_string(number) + ": not valid JSON, and no \"id\" found");
      id = nlohmann::json::parse(*quoted).get<std::string>();
      r.status = Status::nonfinite;
    }
    results.emplace(id, std::move(r));  // the first line of an id counts
  }
  if (in.bad()) throw Unusable("reading candidate " + path + " failed");
  return results;
}

// A plugin (hinge/candidate.h), loaded with dlopen.
class Plugin {
 public:
  Plugin(const std::string& path, const std::string& symbol) {
    handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) throw Unusable("cannot load plugin " + path + ": " + dlerror());
    void* f = dlsym(handle_, symbol.c_str());
    if (!f) {
      const std::string why = dlerror();
      dlclose(handle_);
      throw Unusable("plugin " + path + " has no symbol " + symbol + ": " + why);
    }
    function_ = reinterpret_cast<hinge_candidate_fn*>(f);
  }
  ~Plugin() {
    if (handle_) dlclose(handle_);
  }
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  conf::CandidateResult operator()(const std::array<double, 12>& x) const {
    conf::CandidateResult r;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    r.theta = nan;  // what the plugin leaves unwritten counts as non-finite
    r.grad.fill(nan);
    r.hess.fill(nan);
    const int status = function_(x.data(), &r.theta, r.grad.data(), r.hess.data());
    if (status != 0) {
      r.status = Status::error;
      r.error = "returned " + std::to_string(status);
      return r;
    }
    r.status = Status::ok;
    conf::check_finite(r);
    return r;
  }

 private:
  void* handle_ = nullptr;
  hinge_candidate_fn* function_ = nullptr;
};

std::string eval_line(const std::string& id, const conf::CandidateResult& r) {
  if (r.status == Status::error || r.status == Status::missing)
    return error_line(json_string(id), r.error.empty() ? "cannot evaluate" : r.error);
  if (r.status == Status::nonfinite) return error_line(json_string(id), "non-finite result");
  reference::RoundedTheta v;
  v.theta = r.theta;
  v.grad = r.grad;
  v.hess = r.hess;
  return result_line(json_string(id), v);
}

// One line per case: errors and tolerances (--verbose).
void print_cases(std::ostream& out, const std::vector<conf::CaseOutcome>& outcomes) {
  char line[512];
  std::snprintf(line, sizeof line, "%-44s %-4s %10s %10s %10s %10s %10s %10s\n", "case", "", "theta", "(tol)", "grad", "(tol)",
                "hess", "(tol)");
  out << line;
  for (const auto& o : outcomes) {
    std::snprintf(line, sizeof line, "%-44s %-4s %10.3g %10.3g %10.3g %10.3g %10.3g %10.3g\n", o.id.c_str(),
                  o.pass ? "ok" : "FAIL", o.error[0], o.tolerance[0], o.error[1], o.tolerance[1], o.error[2], o.tolerance[2]);
    out << line;
  }
  out << '\n';
}

int run_cases(const ConformOptions& o) {
  std::optional<Plugin> plugin;
  std::map<std::string, conf::CandidateResult> file;
  std::string name;
  if (!o.candidate.empty()) {
    file = read_candidate(o.candidate);
    name = "candidate " + o.candidate;
  } else {
    plugin.emplace(o.plugin, o.symbol);
    name = "plugin " + o.plugin + " (" + o.symbol + ")";
  }
  std::optional<AtomicFile> saved;
  if (!o.save.empty()) saved.emplace(o.save);

  const std::vector<conf::Case> cases = selected_inputs(o);
  std::vector<conf::CaseOutcome> outcomes;
  Progress progress("hinge conform: cases", cases.size());
  std::size_t unknown = file.size();
  for (const conf::Case& c : cases) {
    const conf::Expected e = conf::expected(c);
    conf::CandidateResult r;
    if (plugin) {
      r = (*plugin)(c.x);
    } else if (auto it = file.find(c.id); it != file.end()) {
      r = it->second;
      --unknown;
    }
    if (saved) saved->stream() << eval_line(c.id, r) << '\n';
    outcomes.push_back(conf::compare(e, r, o.policy));
    progress.update(outcomes.size());
  }
  if (saved) saved->commit();
  if (!plugin && unknown > 0 && o.categories.empty())
    std::cerr << "hinge conform: " << unknown << " line(s) of the candidate have ids that are not conformance cases (ignored)\n";
  if (o.verbose) print_cases(std::cout, outcomes);
  const bool pass = conf::print_report(std::cout, outcomes, o.policy, name);
  return pass ? exit_done : exit_invalid_input;
}

int write_inputs(const ConformOptions& o) {
  std::optional<AtomicFile> file;
  std::ostream* out = &std::cout;
  if (!o.output.empty() && o.output != "-") out = &file.emplace(o.output).stream();
  for (const conf::Case& c : selected_inputs(o)) {
    std::string line = "{\"id\": " + json_string(c.id) + ", \"category\": " + json_string(c.category) + ", \"x\": ";
    append_array(line, c.x.data(), 12);
    line += "}\n";
    *out << line;
  }
  out->flush();
  if (file) file->commit();
  return *out ? exit_done : exit_invalid_input;
}

// ---- mesh files -------------------------------------------------------------------------------------

void write_obj(const std::filesystem::path& path, const Mesh& m, const std::string& comment) {
  AtomicFile f(path.string());
  f.stream() << "# " << comment << "\n";
  std::string line;
  for (const auto& v : m.vertices) {
    line = "v ";
    for (int c = 0; c < 3; ++c) {
      if (c) line += ' ';
      append_double(line, v[c]);
    }
    f.stream() << line << '\n';
  }
  for (const auto& t : m.faces) f.stream() << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  f.commit();
}

// Matrix Market, coordinate real symmetric, lower triangle (as hinge hessian writes it).
void write_mtx(std::ostream& out, const Eigen::SparseMatrix<double>& upper) {
  out << "%%MatrixMarket matrix coordinate real symmetric\n"
      << "% hinge: certified Hessian of the bending energy; lower triangle, 1-based, global index 3 v + c\n"
      << upper.rows() << ' ' << upper.cols() << ' ' << upper.nonZeros() << '\n';
  std::string line;
  for (Eigen::Index c = 0; c < upper.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(upper, c); it; ++it) {
      line = std::to_string(it.col() + 1) + ' ' + std::to_string(it.row() + 1) + ' ';
      append_double(line, it.value());
      out << line << '\n';
    }
}

// A symmetric matrix as its entries (i <= j), 0-based.
using Entries = std::map<std::pair<long, long>, double>;

Entries entries(const Eigen::SparseMatrix<double>& upper) {
  Entries e;
  for (Eigen::Index c = 0; c < upper.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(upper, c); it; ++it) e[{it.row(), it.col()}] += it.value();
  return e;
}

// Reads a Matrix Market coordinate real matrix (symmetric: either triangle; general: both triangles,
// averaged). Throws Unusable.
Entries read_mtx(const std::string& path, long n) {
  std::ifstream in(path);
  if (!in) throw Unusable("cannot read candidate Hessian " + path);
  std::string header;
  std::getline(in, header);
  std::string lower = header;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (lower.rfind("%%matrixmarket matrix coordinate real", 0) != 0)
    throw Unusable(path + ": expected %%MatrixMarket matrix coordinate real symmetric|general");
  const bool symmetric = lower.find("symmetric") != std::string::npos;
  std::string text;
  while (std::getline(in, text) && (text.empty() || text[0] == '%')) {
  }
  long rows = 0, cols = 0, count = 0;
  std::istringstream size(text);
  if (!(size >> rows >> cols >> count) || rows != n || cols != n)
    throw Unusable(path + ": expected a " + std::to_string(n) + " x " + std::to_string(n) + " matrix");
  Entries e;
  for (long k = 0; k < count; ++k) {
    long i = 0, j = 0;
    std::string value;
    if (!(in >> i >> j >> value) || i < 1 || j < 1 || i > n || j > n)
      throw Unusable(path + ": entry " + std::to_string(k + 1) + " is unreadable or out of range");
    double v = 0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc() || end != value.data() + value.size())
      v = std::numeric_limits<double>::quiet_NaN();  // counted as non-finite
    const std::pair<long, long> key{std::min(i, j) - 1, std::max(i, j) - 1};
    e[key] += symmetric || i == j ? v : v / 2;
  }
  return e;
}

double frobenius(const Entries& e) {  // off-diagonal entries count twice
  double largest = 0;
  for (const auto& [k, v] : e) largest = std::max(largest, std::fabs(v));
  if (largest == 0 || !std::isfinite(largest)) return largest;
  double sum = 0;
  for (const auto& [k, v] : e) sum += (k.first == k.second ? 1 : 2) * (v / largest) * (v / largest);
  return largest * std::sqrt(sum);
}

int run_mesh(const ConformOptions& o) {
  if (o.hessian.empty()) throw std::invalid_argument("--mesh needs --hessian H.mtx (the candidate's Hessian)");
  if (o.energy.empty()) throw std::invalid_argument("--mesh needs --energy (tan, shells, willmore, bridson)");
  reference::EnergyParameters parameters;
  parameters.model = reference::parse_model(o.energy);
  parameters.k = o.k;
  Mesh deformed, rest;
  Topology topology;
  try {
    deformed = read_obj(o.mesh);
    rest = o.rest.empty() ? deformed : read_obj(o.rest);
    topology = build_topology(deformed);
    check_faces_nondegenerate(deformed);
    check_faces_nondegenerate(rest);
  } catch (const std::exception& e) {
    std::cerr << "hinge conform: " << e.what() << "\n";
    return exit_usage;
  }
  const oracle::CertifiedMesh m = oracle::certified_mesh(deformed, rest, topology, parameters, reference::want_all);
  const long n = static_cast<long>(3 * topology.vertex_count);
  const Entries want = entries(m.rounded.hessian), got = read_mtx(o.hessian, n);
  Entries difference = want;  // over the union of both patterns; an entry left out is a zero
  for (const auto& [k, v] : got) difference[k] = 0;
  for (auto& [k, v] : difference) {
    const auto w = want.find(k);
    const auto g = got.find(k);
    v = (g == got.end() ? 0.0 : g->second) - (w == want.end() ? 0.0 : w->second);
  }
  constexpr double u = 0x1p-53;
  const double size = frobenius(want);
  const double kappa = conf::hessian_kappa_sum(m);
  const double error = frobenius(difference) / (size > 0 ? size : 1) / u;
  const double tolerance = conf::mesh_base * kappa;
  bool pass = std::isfinite(error) && error <= tolerance;
  std::cout << "hinge conform: mesh " << o.mesh << " (" << topology.hinges.size() << " hinges, energy " << o.energy
            << ", k " << format_double(o.k) << "), certified against the candidate's files\n"
            << "Hessian:  normwise error " << error << " units of 2^-53, tolerance " << tolerance << " = "
            << conf::mesh_base << " kappa_sum (kappa_sum " << kappa << ")\n";
  if (!o.gradient.empty()) {
    std::ifstream in(o.gradient);
    if (!in) throw Unusable("cannot read candidate gradient " + o.gradient);
    std::vector<double> g;
    for (std::string t; in >> t;) {
      double v = std::numeric_limits<double>::quiet_NaN();
      std::from_chars(t.data(), t.data() + t.size(), v);
      g.push_back(v);
    }
    if (static_cast<long>(g.size()) != n) throw Unusable(o.gradient + ": expected " + std::to_string(n) + " numbers");
    double largest = 0;
    for (long i = 0; i < n; ++i) largest = std::max(largest, std::fabs(m.rounded.gradient[i]));
    const double scale = largest > 0 ? largest : 1;
    double d2 = 0, w2 = 0;
    for (long i = 0; i < n; ++i) {
      const double d = (g[i] - m.rounded.gradient[i]) / scale, w = m.rounded.gradient[i] / scale;
      d2 += d * d;
      w2 += w * w;
    }
    const double gsize = std::sqrt(w2) * scale;
    const double gkappa = conf::gradient_kappa_sum(m);
    const double gerror = std::sqrt(d2) * scale / (gsize > 0 ? gsize : 1) / u;
    const double gtolerance = conf::mesh_base * gkappa;
    std::cout << "gradient: normwise error " << gerror << " units of 2^-53, tolerance " << gtolerance << " = "
              << conf::mesh_base << " kappa_sum (kappa_sum " << gkappa << ")\n";
    pass = pass && std::isfinite(gerror) && gerror <= gtolerance;
  }
  std::cout << (pass ? "PASS\n" : "FAIL (exit status 1)\n");
  return pass ? exit_done : exit_invalid_input;
}

// ---- the committed vectors --------------------------------------------------------------------------

int write_vectors(const ConformOptions& o) {
  namespace fs = std::filesystem;
  const fs::path dir(o.write_vectors);
  fs::create_directories(dir / "hinges");
  fs::create_directories(dir / "meshes");
  const std::vector<conf::Case> cases = conf::inputs();
  Progress progress("hinge conform: vectors", cases.size());
  std::size_t done = 0;
  for (const std::string& category : conf::categories()) {
    AtomicFile f((dir / "hinges" / (category + ".jsonl")).string());
    for (const conf::Case& c : cases) {
      if (c.category != category) continue;
      const conf::Expected e = conf::expected(c);
      if (!e.values.uncertified.empty()) throw std::logic_error("conformance case " + c.id + " is not certified");
      std::string line = "{\"id\": " + json_string(c.id) + ", \"category\": " + json_string(c.category) + ", \"x\": ";
      append_array(line, c.x.data(), 12);
      line += ", \"theta\": ";
      append_double(line, e.values.theta);
      line += ", \"grad\": ";
      append_array(line, e.values.grad.data(), 12);
      line += ", \"hess\": ";
      append_array(line, e.values.hess.data(), 144);
      line += ", \"length\": ";
      append_double(line, e.conditioning.length);
      line += ", \"scale\": ";
      append_array(line, e.conditioning.scale.data(), 3);
      line += ", \"kappa\": ";
      append_array(line, e.conditioning.kappa.data(), 3);
      line += ", \"bits\": " + std::to_string(e.values.bits) + "}\n";
      f.stream() << line;
      progress.update(++done);
    }
    f.commit();
  }
  AtomicFile index((dir / "meshes" / "meshes.jsonl").string());
  for (const conf::MeshCase& m : conf::meshes()) {
    write_obj(dir / "meshes" / (m.name + ".obj"), m.deformed, "hinge conformance mesh " + m.name + " (deformed)");
    write_obj(dir / "meshes" / (m.name + "-rest.obj"), m.rest, "hinge conformance mesh " + m.name + " (rest)");
    const Topology t = build_topology(m.deformed);
    for (const char* energy : {"shells", "tan"}) {
      reference::EnergyParameters p;
      p.model = reference::parse_model(energy);
      p.k = 1;
      const oracle::CertifiedMesh c = oracle::certified_mesh(m.deformed, m.rest, t, p, reference::want_all);
      if (!c.uncertified.empty()) throw std::logic_error("conformance mesh " + m.name + " is not certified");
      const std::string stem = m.name + "." + energy;
      AtomicFile h((dir / "meshes" / (stem + ".mtx")).string());
      write_mtx(h.stream(), c.rounded.hessian);
      h.commit();
      AtomicFile g((dir / "meshes" / (stem + ".gradient.txt")).string());
      for (double v : c.rounded.gradient) g.stream() << format_double(v) << '\n';
      g.commit();
      std::string line = "{\"mesh\": " + json_string(m.name + ".obj") + ", \"rest\": " + json_string(m.name + "-rest.obj") +
                         ", \"energy\": " + json_string(energy) + ", \"k\": 1.0, \"hinges\": " +
                         std::to_string(t.hinges.size()) + ", \"value\": ";
      append_double(line, c.rounded.energy);
      line += ", \"hessian\": " + json_string(stem + ".mtx") + ", \"gradient\": " + json_string(stem + ".gradient.txt") +
              ", \"kappa_sum\": ";
      append_double(line, conf::hessian_kappa_sum(c));
      line += ", \"bits\": " + std::to_string(c.bits) + "}\n";
      index.stream() << line;
    }
  }
  index.commit();
  std::cerr << "hinge conform: wrote " << cases.size() << " hinge cases and " << 2 * conf::meshes().size()
            << " mesh cases under " << dir.string() << "\n";
  return exit_done;
}

}  // namespace

Action add_conform(CLI::App& app) {
  auto* cmd = app.add_subcommand("conform", "Check another implementation against certified values");
  auto o = std::make_shared<ConformOptions>();
  cmd->add_flag("--inputs", o->inputs, "Write the conformance inputs as JSON Lines {\"id\", \"category\", \"x\"}");
  cmd->add_option("--output", o->output, "With --inputs: write here (default: standard output)");
  cmd->add_option("--candidate", o->candidate, "Check outputs in the hinge eval format (same ids as --inputs)");
  cmd->add_option("--plugin", o->plugin, "Check a shared library exporting the C function of hinge/candidate.h");
  cmd->add_option("--symbol", o->symbol, "The plugin's function")->capture_default_str();
  cmd->add_option("--save", o->save, "With --plugin: also write its outputs in the hinge eval format");
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
      "output's error is at most base + c kappa (docs/conformance.md). Exit: 0 pass, 1 fail, 2 usage error or\n"
      "unreadable candidate.");
  return [o]() -> int {
    const int modes = int(o->inputs) + int(!o->candidate.empty()) + int(!o->plugin.empty()) +
                      int(!o->write_vectors.empty()) + int(!o->mesh.empty());
    if (modes != 1) {
      std::cerr << "hinge conform: give exactly one of --inputs, --candidate, --plugin, --mesh, --write-vectors\n";
      return exit_usage;
    }
    if (!o->save.empty() && o->plugin.empty()) {
      std::cerr << "hinge conform: --save goes with --plugin\n";
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
    } catch (const std::filesystem::filesystem_error& e) {
      std::cerr << "hinge conform: " << e.what() << "\n";
      return exit_invalid_input;
    } catch (const InputError& e) {
      std::cerr << "hinge conform: " << e.what() << "\n";
      return exit_invalid_input;
    } catch (const DomainError& e) {
      std::cerr << "hinge conform: " << e.what() << "\n";
      return exit_invalid_input;
    }
  };
}

}  // namespace hinge::tools
