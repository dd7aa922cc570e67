// The graded cases of the energy conformance and their expectations (hinge/conformance/energy_sets.hpp).
#include "hinge/conformance/energy_sets.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "hinge/core/errors.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/oracle/conditioning.hpp"
#include "hinge/oracle/mesh.hpp"

namespace hinge::conformance {
namespace {

// Every nonzero output of e within float's normal range, [2^-126, FLT_MAX] in magnitude (once rounded to float).
bool in_float_range(const Expected& e) {
  const auto ok = [](double v) {
    const double f = static_cast<double>(static_cast<float>(v));
    return v == 0 || (std::isfinite(f) && std::fabs(f) >= 0x1p-126);
  };
  if (!ok(e.values.theta)) return false;
  for (const double v : e.values.grad)
    if (!ok(v)) return false;
  for (const double v : e.values.hess)
    if (!ok(v)) return false;
  return true;
}

// Each line of the compiled-in JSON Lines file `name`, parsed (std::logic_error for a line that is not JSON).
template <class F>
void for_each_line(const std::string& name, F f) {
  const std::string_view text = embedded_file(name);
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(begin, end - begin);
    begin = end + 1;
    if (line.empty()) continue;
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded()) throw std::logic_error("conformance set " + name + ": a line is not JSON");
    f(j);
  }
}

// The committed conditioning of an energy's cases (energies/<energy>.jsonl): for k = 1 and the contract's
// weight, that of psi, the gradient and the exact Hessian, and of the Gauss-Newton Hessian.
struct CommittedConditioning {
  oracle::Conditioning exact;
  double scale_gauss_newton = 0, kappa_gauss_newton = 0;
};
const std::map<std::string, CommittedConditioning>& committed(const std::string& energy, Dtype dtype) {
  static std::mutex mutex;
  static std::map<std::string, std::map<std::string, CommittedConditioning>> cache;
  const std::lock_guard lock(mutex);
  const std::string name = energy_conditioning_file(energy, dtype);
  auto [it, fresh] = cache.try_emplace(name);
  if (!fresh) return it->second;
  for_each_line(name, [&](const nlohmann::json& j) {
    CommittedConditioning c;
    c.exact.length = j.at("length").get<double>();
    c.exact.scale = j.at("scale").get<std::array<double, 3>>();
    c.exact.kappa = j.at("kappa").get<std::array<double, 3>>();
    if (j.contains("scale_gauss_newton")) {  // not for quadratic (one Hessian)
      c.scale_gauss_newton = j.at("scale_gauss_newton").get<double>();
      c.kappa_gauss_newton = j.at("kappa_gauss_newton").get<double>();
    }
    it->second.emplace(j.at("id").get<std::string>(), c);
  });
  return it->second;
}

// The committed 256-bit projected Hessians of an energy's cases (energies/<energy>.projected.jsonl: per case its
// upper triangle, row by row, 78 numbers), for k = 1 and the contract's weight.
const std::map<std::string, std::array<double, 144>>& committed_projected(const std::string& energy) {
  static std::mutex mutex;
  static std::map<std::string, std::map<std::string, std::array<double, 144>>> cache;
  const std::lock_guard lock(mutex);
  auto [it, fresh] = cache.try_emplace(energy);
  if (!fresh) return it->second;
  const std::string name = "energies/" + energy + ".projected.jsonl";
  for_each_line(name, [&](const nlohmann::json& j) {
    const auto upper = j.at("hess_upper").get<std::vector<double>>();
    if (upper.size() != 78) throw std::logic_error("conformance set " + name + ": hess_upper needs 78 numbers");
    std::array<double, 144> h{};
    std::size_t k = 0;
    for (int row = 0; row < 12; ++row)
      for (int col = row; col < 12; ++col) h[12 * row + col] = h[12 * col + row] = upper[k++];
    it->second.emplace(j.at("id").get<std::string>(), h);
  });
  return it->second;
}

}  // namespace

namespace {

// e's outputs rounded to float (held in doubles): the certified doubles, each within half a unit of double of
// the exact value, round to the float nearest the exact value unless the double is a midpoint between two
// floats; such an output is flagged uncertified (the exact value may lie on either side).
void round_to_float(Expected& e) {
  const auto round = [&](double& v, const std::string& name) {
    const float f = static_cast<float>(v);
    const float other = std::nextafter(f, v > static_cast<double>(f) ? INFINITY : -INFINITY);
    if (v != static_cast<double>(f) && v == (static_cast<double>(f) + static_cast<double>(other)) / 2)
      e.values.uncertified.push_back({name, "", "", static_cast<double>(f)});
    v = static_cast<double>(f);
  };
  round(e.values.theta, "energy");
  for (int i = 0; i < 12; ++i) round(e.values.grad[i], "grad[" + std::to_string(i) + "]");
  for (int i = 0; i < 144; ++i) round(e.values.hess[i], "hess[" + std::to_string(i) + "]");
}

}  // namespace

std::string energy_conditioning_file(const std::string& energy, Dtype dtype) {
  return (dtype == Dtype::float32 ? "energies-float32/" : "energies/") + energy + ".jsonl";
}

const EnergySet& energy_set(Model model, Depth depth, Dtype dtype) {
  if (model == Model::viscoelastic) throw std::invalid_argument("the viscoelastic energy is not graded");
  if (dtype == Dtype::float32 && depth == Depth::deep)
    throw std::invalid_argument("the energy conformance in float32 offers depth \"quick\" only (yet)");
  static std::mutex mutex;
  static std::map<std::tuple<Model, Depth, Dtype>, EnergySet> cache;
  const std::lock_guard lock(mutex);
  auto [it, fresh] = cache.try_emplace({model, depth, dtype});
  if (!fresh) return it->second;
  it->second.depth = depth;
  it->second.dtype = dtype;
  EnergyInputs inputs =
      dtype == Dtype::float32 ? float32_energy_inputs(energy_per_category) : energy_inputs(energy_per_category);
  if (depth == Depth::deep) {  // the quick pairs, then the hard families' (joining their categories in the report)
    EnergyInputs deep = deep_energy_inputs(energy_per_family_deep);
    for (EnergyCase& c : deep.cases) inputs.cases.push_back(std::move(c));
    for (std::string& id : deep.left_out) inputs.left_out.push_back(std::move(id));
  }
  for (std::string& id : inputs.left_out) it->second.left_out.push_back(id + ": |theta - theta_bar| > pi");
  for (EnergyCase& c : inputs.cases) {
    if (infinite_at_pi(model) || dtype == Dtype::float32) try {
        EnergyProblem p;
        p.model = model;
        const Expected e = energy_expected(c, p, false);
        if (dtype == Dtype::float32 && !in_float_range(e)) {
          it->second.left_out.push_back(c.id + ": an output outside float's normal range");
          continue;
        }
      } catch (const DomainError& e) {
        it->second.left_out.push_back(c.id + ": " + e.what());
        continue;
      }
    it->second.cases.push_back(std::move(c));
  }
  return it->second;
}

const EnergySet& quadratic_set(Depth depth, Dtype dtype) {
  if (dtype == Dtype::float32 && depth == Depth::deep)
    throw std::invalid_argument("the energy conformance in float32 offers depth \"quick\" only (yet)");
  static std::mutex mutex;
  static std::map<std::pair<Depth, Dtype>, EnergySet> cache;
  const std::lock_guard lock(mutex);
  auto [it, fresh] = cache.try_emplace({depth, dtype});
  if (!fresh) return it->second;
  it->second = [depth, dtype] {
    EnergySet out;
    out.depth = depth;
    out.dtype = dtype;
    EnergyInputs inputs =
        dtype == Dtype::float32 ? float32_energy_inputs(energy_per_category) : energy_inputs(energy_per_category);
    if (depth == Depth::deep)
      for (EnergyCase& c : deep_energy_inputs(energy_per_family_deep).cases) inputs.cases.push_back(std::move(c));
    std::vector<EnergyCase> flat, at_rest;
    for (const EnergyCase& c : inputs.cases) {
      const std::size_t slash = c.category.find('/');
      if (c.category.substr(slash + 1) != "flat") continue;
      flat.push_back(c);
      const std::string deformed = c.category.substr(0, slash);
      const std::string tag = c.id.substr(c.category.size() + 1);
      at_rest.push_back({deformed + "/at-rest/" + tag, deformed + "/at-rest", c.rest, c.rest});
    }
    // In category order (the deep families not among the categories after them): each deformed category's
    // flat pairs, then its at-rest ones.
    std::vector<std::string> order = categories();
    for (const std::string& family : hard_families())
      if (std::find(order.begin(), order.end(), family) == order.end()) order.push_back(family);
    for (const std::string& category : order)
      for (const auto* list : {&flat, &at_rest})
        for (const EnergyCase& c : *list)
          if (c.category.starts_with(category + "/")) out.cases.push_back(c);
    return out;
  }();
  return it->second;
}

const EnergySet& energy_set_of(const EnergyProblem& problem, Depth depth, Dtype dtype) {
  return problem.quadratic ? quadratic_set(depth, dtype) : energy_set(problem.model, depth, dtype);
}

const std::vector<std::string>& weight_names() {
  static const std::vector<std::string> names{"contract", "bridson", "edge-length", "unit"};
  return names;
}

double named_weight(const std::string& name, const std::array<double, 12>& rest) {
  const RestShape s = rest_shape(rest);
  const double edge_over_area = s.edge / (s.area0 + s.area3);  // no |e_bar|^2 formed: it may overflow
  if (name == "contract") return 3 * edge_over_area * s.edge;  // Discrete Shells: |e_bar| / h_bar_e
  if (name == "bridson") return edge_over_area * s.edge / 2;   // |e_bar|^2 / (|N1| + |N2|)
  if (name == "edge-length") return s.edge;
  if (name == "unit") return 1;
  std::string choices;
  for (const std::string& n : weight_names()) choices += (choices.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown weight '" + name + "' (expected " + choices + ", or a callable)");
}

void keep_diagonal_blocks(double* hess) {
  for (int row = 0; row < 12; ++row)
    for (int col = 0; col < 12; ++col)
      if (row / 3 != col / 3) hess[12 * row + col] = 0;
}

std::vector<Expected> energy_expectations(const EnergySet& set, const EnergyProblem& problem,
                                          const std::vector<double>& weights, Dtype dtype, bool diagonal_blocks) {
  if (dtype != set.dtype) throw std::invalid_argument("energy_expectations: the set is for another dtype");
  if (!weights.empty() && weights.size() != set.cases.size())
    throw std::invalid_argument("energy_expectations: one weight per case");
  if (problem.quadratic && !weights.empty()) throw std::invalid_argument("the quadratic energy takes no weight");
  const std::string energy = energy_name(problem);
  const auto& table = committed(energy, dtype);
  std::vector<Expected> out;
  out.reserve(set.cases.size());
  for (std::size_t i = 0; i < set.cases.size(); ++i) {
    const EnergyCase& c = set.cases[i];
    const auto found = table.find(c.id);
    const std::optional<double> w = weights.empty() ? std::nullopt : std::optional<double>(weights[i]);
    if (found == table.end()) {  // a deep case: its conditioning (and a projected reference) computed now
      if (c.id.find("/deep-") == std::string::npos)
        throw std::logic_error("energies/" + energy + ".jsonl has no case " + c.id);
      Expected e = energy_expected(c, problem, true, w);
      if (diagonal_blocks) {
        keep_diagonal_blocks(e.values.hess.data());
        const double size = oracle::scaled_norm(e.values.hess.data(), 144);
        e.conditioning.kappa[2] = size > 0 ? e.conditioning.scale[2] / size : 1.0;
      }
      out.push_back(std::move(e));
      continue;
    }
    const bool projected = problem.hessian == HessianKind::projected;
    if (projected && dtype == Dtype::float32)
      throw std::invalid_argument("hessian \"projected\" is graded in float64 only (its reference is not a float's)");
    EnergyProblem certified = problem;  // projected: the certified outputs, then the committed reference
    if (projected) certified.hessian = HessianKind::exact;
    Expected e = energy_expected(c, certified, false, w);
    const CommittedConditioning& k = found->second;
    const double factor = problem.k * (w ? *w / named_weight("contract", c.rest) : 1.0);
    e.conditioning = k.exact;
    if (problem.hessian == HessianKind::gauss_newton) {
      e.conditioning.scale[2] = k.scale_gauss_newton;
      e.conditioning.kappa[2] = k.kappa_gauss_newton;
    }
    for (double& s : e.conditioning.scale) s *= std::fabs(factor);
    if (projected) {
      const auto& references = committed_projected(energy);
      const auto reference = references.find(c.id);
      if (reference == references.end())
        throw std::logic_error("energies/" + energy + ".projected.jsonl has no case " + c.id);
      for (int j = 0; j < 144; ++j) e.values.hess[j] = reference->second[j] * factor;
      e.values.uncertified.clear();  // the Hessian is not certified at all: the report says so
      set_projected_kappa(e);
    }
    if (dtype == Dtype::float32) round_to_float(e);
    if (e.values.theta == 0) apply_zero_energy_bound(e, c, problem, w, dtype);
    if (diagonal_blocks) {
      keep_diagonal_blocks(e.values.hess.data());
      const double size = oracle::scaled_norm(e.values.hess.data(), 144);
      e.conditioning.kappa[2] = size > 0 ? e.conditioning.scale[2] / size : 1.0;
    }
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace hinge::conformance
