// summary.json (hinge/io/summary.hpp).
#include "hinge/io/summary.hpp"

#include <nlohmann/json.hpp>

namespace hinge::io {

std::string summary_json(const Summary& s, const std::vector<std::pair<std::string, std::string>>& build) {
  using json = nlohmann::ordered_json;  // numbers as the shortest decimal that reads back exactly
  json j;
  j["scene"] = s.scene;
  j["status"] = s.ok ? "ok" : "failed";
  if (!s.ok) j["reason"] = s.reason;
  j["effects"] = s.effects;
  j["vertices"] = s.vertices;
  j["steps"] = s.steps;
  j["newton_iterations"] = s.newton_iterations;
  json effects = json::object();
  for (const auto& [name, t] : s.time_effects) effects[name] = t;
  j["time_s"] = {{"total", s.time_total}, {"linear_solve", s.time_linear_solve}, {"effects", effects}};
  json energy = json::object();
  for (const auto& [name, e] : s.energy) energy[name] = e;
  j["energy"] = energy;
  j["bending_share"] = s.bending_share;
  const SolverReport& r = s.solver;
  j["solver"] = {
      {"factorizations", r.factorizations},
      {"shifted", r.shifted},
      {"newton_per_step", {{"median", r.newton_median}, {"max", r.newton_max}}},
      {"rungs",
       {{"newton", r.newton}, {"projected", r.projected}, {"shifted", r.shifted_rung}, {"gradient", r.gradient}}},
      {"halvings", r.halvings},
      {"limited", r.limited},
      {"linear_solver", r.linear_solver}};
  json b = json::object();
  for (const auto& [k, v] : build) b[k] = v;
  j["build"] = b;
  return j.dump(2) + "\n";
}

}  // namespace hinge::io
