// The committed conformance vectors, written (hinge/conformance/vectors.hpp, docs/conformance-format.md).
// Every hinge case certified by certified_with_conditioning (stages 1 and 2 of the oracle, so that "bits"
// records the enclosures' precision), in binary64 or binary32.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "hinge/conformance/energy_sets.hpp"
#include "hinge/conformance/grading.hpp"
#include "hinge/conformance/vectors.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/io/atomic_file.hpp"
#include "hinge/io/jsonl.hpp"
#include "hinge/io/matrix_market.hpp"
#include "hinge/io/number.hpp"
#include "hinge/io/obj.hpp"
#include "hinge/oracle/projected.hpp"

namespace hinge::conformance {
namespace {

using namespace oracle;  // the certifier: exact_hinge, certify, certified_mesh, ...

void write_mesh(const std::filesystem::path& path, const Mesh& m, const std::string& comment) {
  io::AtomicFile f(path.string());
  io::write_obj(f.stream(), m, comment);
  f.commit();
}

std::string hinge_line(const Expected& e) {
  std::string line = io::input_line(e.input.id, e.input.category, e.input.x);
  line.pop_back();  // '}'
  const auto numbers = [&](const char* key, const double* values, std::size_t count) {
    line += std::string(", \"") + key + "\": ";
    if (count == 1) io::append_double(line, *values);
    else io::append_array(line, values, count);
  };
  numbers("theta", &e.values.theta, 1);
  numbers("grad", e.values.grad.data(), 12);
  numbers("hess", e.values.hess.data(), 144);
  numbers("length", &e.conditioning.length, 1);
  numbers("scale", e.conditioning.scale.data(), 3);
  numbers("kappa", e.conditioning.kappa.data(), 3);
  line += ", \"bits\": " + std::to_string(e.values.bits) + "}\n";
  return line;
}

// One set's file per category, in the order of `cases` (category by category as generated). A case that
// cannot be certified is an error (`required`) or dropped and counted.
struct SetWriter {
  const std::filesystem::path& dir;
  const std::function<void(std::size_t, std::size_t)>& progress;
  std::size_t done = 0, total = 0;

  // Returns the cases written; adds the dropped ones to `invalid` and `uncertified`.
  std::size_t write(const std::string& subdir, const std::vector<std::string>& file_categories,
                    const std::vector<Case>& cases, bool binary32, bool required, std::size_t& invalid,
                    std::size_t& uncertified) {
    std::filesystem::create_directories(dir / subdir);
    Options options;
    options.binary32 = binary32;
    std::size_t written = 0;
    for (const std::string& category : file_categories) {
      io::AtomicFile f((dir / subdir / (category + ".jsonl")).string());
      for (const Case& c : cases) {
        if (c.category != category) continue;
        if (progress) progress(++done, total);
        Expected e{c, {}, {}};
        try {
          ConditionedTheta t = certified_with_conditioning(c.x, options);
          e.values = std::move(t.values);
          e.conditioning = t.conditioning;
        } catch (const InputError&) {
          if (required) throw;
          ++invalid;
          continue;
        } catch (const DomainError&) {
          if (required) throw;
          ++invalid;
          continue;
        }
        if (!e.values.uncertified.empty()) {
          if (required) throw std::logic_error("conformance case " + c.id + " is not certified");
          ++uncertified;
          continue;
        }
        f.stream() << hinge_line(e);
        ++written;
      }
      f.commit();
    }
    return written;
  }
};

// The opening of an energies/ line: {"id", "length", "scale", "kappa" (psi, gradient, exact Hessian), without the
// closing brace.
std::string conditioning_fields(const std::string& id, const Conditioning& k) {
  std::string line = "{\"id\": " + io::json_string(id) + ", \"length\": ";
  io::append_double(line, k.length);
  line += ", \"scale\": ";
  io::append_array(line, k.scale.data(), 3);
  line += ", \"kappa\": ";
  io::append_array(line, k.kappa.data(), 3);
  return line;
}

// One line of energies/<energy>.jsonl (docs/conformance-format.md, "energies/"): the conditioning of a case for
// k = 1 and the contract's weight, of psi, its gradient and exact Hessian, and of the Gauss-Newton Hessian.
std::string energy_line(const EnergyCase& c, Model model) {
  EnergyProblem problem;
  problem.model = model;
  EnergyParameters parameters;
  parameters.model = model;
  const Expected exact = energy_expected(c, problem, false);
  problem.hessian = HessianKind::gauss_newton;
  const Expected gauss_newton = energy_expected(c, problem, false);
  const Conditioning k =
      energy_conditioning(c.x, c.rest, parameters, false, exact.values.theta, exact.values.grad, exact.values.hess);
  const Conditioning g = energy_conditioning(c.x, c.rest, parameters, true, gauss_newton.values.theta,
                                             gauss_newton.values.grad, gauss_newton.values.hess);
  std::string line = conditioning_fields(c.id, k);
  line += ", \"scale_gauss_newton\": ";
  io::append_double(line, g.scale[2]);
  line += ", \"kappa_gauss_newton\": ";
  io::append_double(line, g.kappa[2]);
  return line + "}\n";
}

// line(c) for every case, on every core (each line depends on its case alone, and the oracle's working
// precision is per thread), in the cases' order; progress reported as each completes. The first exception a
// thread meets is rethrown.
template <class Line>
std::vector<std::string> energy_lines(const std::vector<EnergyCase>& cases, Line line, SetWriter& w) {
  std::vector<std::string> out(cases.size());
  std::atomic<std::size_t> next{0};
  std::mutex mutex;  // progress and the first error
  std::exception_ptr error;
  const auto work = [&] {
    for (std::size_t i; (i = next++) < cases.size();) {
      try {
        out[i] = line(cases[i]);
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        return;
      }
      const std::lock_guard lock(mutex);
      ++w.done;
      if (w.progress) w.progress(w.done, w.total);
    }
  };
  std::vector<std::thread> threads(std::max(1u, std::thread::hardware_concurrency()) - 1);
  for (std::thread& t : threads) t = std::thread(work);
  work();
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  return out;
}

constexpr Model graded_energies[] = {Model::shells, Model::tan, Model::willmore, Model::bridson};

// One line of energies/<energy>.projected.jsonl: the 256-bit projected Hessian (k = 1, the contract's weight),
// its upper triangle row by row.
std::string projected_line(const EnergyCase& c, Model model) {
  EnergyParameters parameters;
  parameters.model = model;
  const std::array<double, 144> h = projected_hessian_256(c.x, c.rest, parameters);
  std::vector<double> upper;
  for (int row = 0; row < 12; ++row)
    for (int col = row; col < 12; ++col) upper.push_back(h[12 * row + col]);
  std::string line = "{\"id\": " + io::json_string(c.id) + ", \"hess_upper\": ";
  io::append_array(line, upper.data(), upper.size());
  return line + "}\n";
}

// The same for the quadratic energy (no Gauss-Newton Hessian: its keys are left out).
std::string quadratic_line(const EnergyCase& c) {
  EnergyProblem problem;
  problem.quadratic = true;
  const Expected e = energy_expected(c, problem, false);
  const Conditioning k = quadratic_conditioning(c.x, c.rest, 1.0, e.values.theta, e.values.grad, e.values.hess);
  std::string line = conditioning_fields(c.id, k);
  return line + "}\n";
}

}  // namespace

VectorsSummary write_vectors(const std::filesystem::path& dir,
                             const std::function<void(std::size_t, std::size_t)>& progress) {
  namespace fs = std::filesystem;
  fs::create_directories(dir / "meshes");
  const std::vector<Case> quick = inputs(), float32 = float32_inputs(), deep = deep_inputs(),
                          deep32 = deep_float32_inputs();
  VectorsSummary summary;
  SetWriter w{dir, progress};
  w.total = quick.size() + float32.size() + deep.size() + deep32.size();
  for (const Model model : graded_energies) w.total += 2 * energy_set(model).cases.size();
  w.total += quadratic_set().cases.size() + quadratic_set(Depth::quick, Dtype::float32).cases.size();
  for (const Model model : graded_energies) w.total += energy_set(model, Depth::quick, Dtype::float32).cases.size();
  std::size_t none = 0;
  summary.quick = w.write("hinges", categories(), quick, false, true, none, none);
  summary.float32 = w.write("hinges-float32", categories(), float32, true, true, none, none);
  summary.deep_draws = summary.deep_float32_draws = hard_families().size() * deep_per_family;
  summary.deep_invalid = summary.deep_draws - deep.size();  // the draws hard_cases dropped
  summary.deep = w.write("deep", hard_families(), deep, false, false, summary.deep_invalid, summary.deep_uncertified);
  summary.deep_float32_invalid = summary.deep_float32_draws - deep32.size();
  summary.deep_float32 = w.write("deep-float32", hard_families(), deep32, true, false, summary.deep_float32_invalid,
                                 summary.deep_float32_uncertified);
  // The energies' lines, each case's independent of the others: made on every core (energy_lines).
  const auto write = [&](const fs::path& path, const std::vector<EnergyCase>& cases, auto line) {
    io::AtomicFile f(path.string());
    for (const std::string& l : energy_lines(cases, line, w)) f.stream() << l;
    f.commit();
  };
  fs::create_directories(dir / "energies");
  for (const Model model : graded_energies) {
    const std::vector<EnergyCase>& cases = energy_set(model).cases;
    const std::string name(model_name(model));
    write(dir / "energies" / (name + ".jsonl"), cases, [model](const EnergyCase& c) { return energy_line(c, model); });
    write(dir / "energies" / (name + ".projected.jsonl"), cases,
          [model](const EnergyCase& c) { return projected_line(c, model); });
    summary.energy_cases += cases.size();
  }
  write(dir / "energies" / "quadratic.jsonl", quadratic_set().cases, quadratic_line);
  summary.energy_cases += quadratic_set().cases.size();
  // The float32 pairs' conditioning (of the exact values: the same lines' format; no projected references).
  fs::create_directories(dir / "energies-float32");
  for (const Model model : graded_energies) {
    const std::vector<EnergyCase>& cases = energy_set(model, Depth::quick, Dtype::float32).cases;
    write(dir / "energies-float32" / (std::string(model_name(model)) + ".jsonl"), cases,
          [model](const EnergyCase& c) { return energy_line(c, model); });
    summary.energy_cases += cases.size();
  }
  write(dir / "energies-float32" / "quadratic.jsonl", quadratic_set(Depth::quick, Dtype::float32).cases,
        quadratic_line);
  summary.energy_cases += quadratic_set(Depth::quick, Dtype::float32).cases.size();

  io::AtomicFile index((dir / "meshes" / "meshes.jsonl").string());
  for (const MeshCase& m : meshes()) {
    write_mesh(dir / "meshes" / (m.name + ".obj"), m.deformed, "hinge conformance mesh " + m.name + " (deformed)");
    write_mesh(dir / "meshes" / (m.name + "-rest.obj"), m.rest, "hinge conformance mesh " + m.name + " (rest)");
    const Topology t = build_topology(m.deformed);
    for (const char* energy : {"shells", "tan"}) {
      EnergyParameters p;
      p.model = parse_model(energy);
      p.k = 1;
      Options enclosures;  // the vectors record the enclosures' working precision ("bits")
      enclosures.fast_path = false;
      const CertifiedMesh c = certified_mesh(m.deformed, m.rest, t, p, want_all, enclosures);
      if (!c.uncertified.empty()) throw std::logic_error("conformance mesh " + m.name + " is not certified");
      const std::string stem = m.name + "." + energy;
      io::AtomicFile h((dir / "meshes" / (stem + ".mtx")).string());
      io::write_matrix_market(
          h.stream(), c.rounded.hessian,
          "hinge: certified Hessian of the bending energy; lower triangle, 1-based, global index 3 v + c");
      h.commit();
      io::AtomicFile g((dir / "meshes" / (stem + ".gradient.txt")).string());
      io::write_numbers(g.stream(), c.rounded.gradient);
      g.commit();
      std::string line = "{\"mesh\": " + io::json_string(m.name + ".obj") +
                         ", \"rest\": " + io::json_string(m.name + "-rest.obj") +
                         ", \"energy\": " + io::json_string(energy) +
                         ", \"k\": 1.0, \"hinges\": " + std::to_string(t.hinges.size()) + ", \"value\": ";
      io::append_double(line, c.rounded.energy);
      line += ", \"hessian\": " + io::json_string(stem + ".mtx") +
              ", \"gradient\": " + io::json_string(stem + ".gradient.txt") + ", \"kappa_sum\": ";
      io::append_double(line, hessian_kappa_sum(c));
      line += ", \"bits\": " + std::to_string(c.bits) + "}\n";
      index.stream() << line;
    }
  }
  index.commit();
  summary.meshes = 2 * meshes().size();
  return summary;
}

}  // namespace hinge::conformance
