// The bending problem's checks and their sentences (hinge/core/bending_problem.hpp).
#include "hinge/core/bending_problem.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <thread>

namespace hinge {

namespace {

// The value as given, shortest round trip ("0.7", "-1", "1e+300", "inf", "nan").
std::string shown(double value) {
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc() ? std::string(buffer, end) : std::string("?");
}

[[noreturn]] void out_of_range(const Parameter& p, const char* rule) {
  throw ParameterError(p.name, std::string(rule) + ", got " + shown(p.value));
}

constexpr Energy evaluated[] = {Energy::shells, Energy::tan, Energy::willmore, Energy::bridson};
constexpr Energy graded[] = {Energy::shells,  Energy::tan,       Energy::willmore,
                             Energy::bridson, Energy::quadratic, Energy::custom};
constexpr Energy all[] = {Energy::shells,       Energy::tan,       Energy::willmore, Energy::bridson,
                          Energy::viscoelastic, Energy::quadratic, Energy::custom};

// Energy's first five are Model's, in its order.
static_assert(static_cast<int>(Energy::shells) == static_cast<int>(Model::shells) &&
              static_cast<int>(Energy::tan) == static_cast<int>(Model::tan) &&
              static_cast<int>(Energy::willmore) == static_cast<int>(Model::willmore) &&
              static_cast<int>(Energy::bridson) == static_cast<int>(Model::bridson) &&
              static_cast<int>(Energy::viscoelastic) == static_cast<int>(Model::viscoelastic));

// The name among `accepted`; the refusals of the header otherwise.
template <std::size_t N>
Energy parse_energy(std::string_view value, std::string_view name, const Energy (&accepted)[N]) {
  for (Energy e : all) {
    if (energy_name(e) != value) continue;
    if (std::find(std::begin(accepted), std::end(accepted), e) != std::end(accepted)) return e;
    switch (e) {
      case Energy::viscoelastic:
        throw ParameterError(name,
                             "the viscoelastic energy is library-only: it needs a previous state and a time step");
      case Energy::quadratic:
        throw ParameterError(name, "the quadratic energy is conformance-only: hinge has no evaluator for it");
      case Energy::custom:
        throw ParameterError(name, "the custom energy is conformance-only: it is a candidate's own energy");
      default: break;
    }
  }
  std::string list;
  for (Energy e : accepted) list += (list.empty() ? "" : ", ") + std::string(energy_name(e));
  throw ParameterError(name, "unknown energy '" + std::string(value) + "' (expected one of " + list + ")");
}

}  // namespace

ParameterError::ParameterError(std::string_view name, const std::string& why)
    : std::invalid_argument(name.empty() ? why : std::string(name) + ": " + why), parameter_(name) {}

std::string_view energy_name(Energy energy) {
  switch (energy) {
    case Energy::quadratic: return "quadratic";
    case Energy::custom: return "custom";
    default: return model_name(static_cast<Model>(energy));
  }
}

std::optional<Model> evaluator_model(Energy energy) {
  if (energy == Energy::quadratic || energy == Energy::custom) return std::nullopt;
  return static_cast<Model>(energy);
}

std::string_view evaluated_energy_names() { return "shells, tan, willmore, bridson"; }

Model parse_bending_energy(std::string_view value, std::string_view name) {
  return static_cast<Model>(parse_energy(value, name, evaluated));
}

Energy parse_graded_energy(std::string_view value, std::string_view name) { return parse_energy(value, name, graded); }

double check_k(Parameter k) {
  if (!(std::isfinite(k.value) && k.value >= 0)) out_of_range(k, "the bending stiffness k must be finite and >= 0");
  return k.value;
}

double check_young(Parameter young) {
  if (!(std::isfinite(young.value) && young.value > 0)) out_of_range(young, "Young's modulus Y must be finite and > 0");
  return young.value;
}

double check_poisson(Parameter poisson) {
  if (!(poisson.value > -1 && poisson.value <= 0.5)) out_of_range(poisson, "Poisson's ratio nu must be in (-1, 0.5]");
  return poisson.value;
}

double check_thickness(Parameter thickness) {
  if (!(std::isfinite(thickness.value) && thickness.value > 0))
    out_of_range(thickness, "the thickness h must be finite and > 0");
  return thickness.value;
}

double stiffness_from_material(Parameter young, Parameter poisson, Parameter thickness) {
  const double Y = check_young(young), nu = check_poisson(poisson), h = check_thickness(thickness);
  const double k = bending_stiffness(Y, nu, h);  // eq. (11)
  if (!std::isfinite(k))
    throw ParameterError(
        std::string(young.name) + ", " + std::string(poisson.name) + ", " + std::string(thickness.name),
        "k = Y h^3 / (24 (1 - nu^2)) (eq. (11)) overflows double");
  return k;
}

BendingProblem bending_problem(Parameter k, std::string_view energy, std::string_view energy_name) {
  return {parse_bending_energy(energy, energy_name), check_k(k)};
}

BendingProblem bending_problem(Parameter young, Parameter poisson, Parameter thickness, std::string_view energy,
                               std::string_view energy_name) {
  return {parse_bending_energy(energy, energy_name), stiffness_from_material(young, poisson, thickness)};
}

void check_bending_mesh(const Topology& topology, const Mesh& deformed, const Mesh* rest, const MeshCheck& check) {
  const auto prefix = [](std::string_view where) { return where.empty() ? std::string() : std::string(where) + ": "; };
  if (topology.hinges.empty() && !check.allow_no_hinges)
    throw InputError(
        prefix(check.deformed) + "the mesh has no interior edge, so its bending energy is 0 whatever its shape" +
        (check.allow_option.empty() ? std::string() : " (" + std::string(check.allow_option) + " if that is meant)"));
  const auto faces = [&](const Mesh& mesh, std::string_view where) {
    try {
      check_faces_nondegenerate(mesh);
    } catch (const InputError& e) {
      if (where.empty()) throw;
      throw InputError(prefix(where) + e.what());
    }
  };
  faces(deformed, check.deformed);
  if (rest && rest != &deformed) faces(*rest, check.rest);
}

int resolve_threads(long long requested, std::string_view name) {
  if (requested < 0 || requested > max_threads)
    throw ParameterError(name, "threads must be in [0, " + std::to_string(max_threads) + "] (0: all cores), got " +
                                   std::to_string(requested));
  if (requested > 0) return static_cast<int>(requested);
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace hinge
