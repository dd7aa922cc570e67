// study.json (hinge/io/study_json.hpp).
#include "hinge/io/study_json.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

namespace hinge::io {
namespace {

using json = nlohmann::ordered_json;
constexpr const char* groups[3] = {"theta", "grad", "hess"};

json group_errors(const GroupErrors& e) {
  json j;
  for (int g = 0; g < 3; ++g)
    j[groups[g]] = {{"median", e[g].median}, {"max", e[g].max}, {"max_bits", error_bits(e[g].max)}};
  return j;
}

}  // namespace

double error_bits(double units) { return std::log2(1 + units); }

std::string row_label(const StudyRow& r) { return r.outside ? r.method : r.method + "/" + r.scalar.name(); }

void write_study_json(std::ostream& out, const Study& s) {
  json j;
  j["version"] = 2;
  j["machine"] = {{"cpu", s.cpu}, {"clock_ghz", s.clock_ghz}};
  j["inputs"] = {{"source", s.source}, {"hinges", s.hinges}, {"skipped", s.skipped}, {"categories", s.categories}};
  j["quick"] = s.quick;
  j["seconds"] = s.seconds;
  j["timing_seconds"] = s.timing_seconds;
  json build = json::object();
  for (const auto& [k, v] : s.build) build[k] = v;
  j["build"] = build;
  json timing = json::object();
  for (const auto& [k, v] : s.timing) timing[k] = v;
  j["timing"] = timing;
  j["units"] = "normwise error in units of 2^-53 (error_u) or of the type's own unit roundoff (error_own)";
  json rows = json::array();
  for (const StudyRow& r : s.rows) {
    json row;
    row["method"] = r.method;
    row["scalar"] = r.scalar.name();
    row["outside"] = r.outside;
    json t = json::object(), c = json::object(), x = json::object();
    for (int g = 0; g < 3; ++g)
      if (r.ns_per_hinge[g] > 0) {
        t[groups[g]] = r.ns_per_hinge[g];
        if (s.clock_ghz > 0) c[groups[g]] = r.ns_per_hinge[g] * s.clock_ghz;
        x[groups[g]] = r.x_fast[g];
      }
    row["ns_per_hinge"] = t;
    row["cycles_per_hinge"] = c;
    row["x_fast"] = x;
    row["rounds"] = r.rounds;
    if (!r.escalation.empty()) row["escalation"] = r.escalation;
    if (!r.error.empty()) row["error"] = r.error;
    json e = json::object(), own = json::object();
    for (const auto& [category, errors] : r.error_u) e[category] = group_errors(errors);
    for (const auto& [category, errors] : r.error_own) own[category] = group_errors(errors);
    row["error_u"] = e;
    if (!r.error_own.empty()) row["error_own"] = own;
    row["nonfinite"] = r.nonfinite;
    row["failed"] = r.failed;
    row["hinges_measured"] = r.hinges;
    row["worst_u"] = r.worst;
    row["worst_hess_u"] = r.worst_hess;
    row["on_frontier"] = r.on_frontier;
    row["seconds"] = r.seconds;
    json h = json::array();  // the Hessian's error per hinge, 3 significant digits (the histogram's data)
    for (const double v : r.hess_errors) {
      char b[32];
      std::snprintf(b, sizeof b, "%.3g", v);
      h.push_back(std::stod(b));
    }
    row["hess_errors_u"] = h;
    rows.push_back(row);
  }
  j["rows"] = rows;
  json mesh = json::array();
  for (const StudyMeshRow& m : s.mesh) {
    json row;
    row["method"] = method_name(m.method);
    row["scalar"] = m.scalar.name();
    row["vertices"] = m.vertices;
    row["interior_edges"] = m.interior_edges;
    row["seconds"] = m.seconds;
    row["ns_per_edge"] = m.ns_per_edge;
    if (m.vertices.size() >= 2) {
      row["k"] = m.k;
      row["ln_a"] = m.ln_a;
    }
    mesh.push_back(row);
  }
  j["mesh"] = mesh;
  if (const SharedFit& f = s.shared_fit; !f.ln_a.empty()) {
    json t = {{"scalar", "double"}, {"k", f.k}};
    for (const auto& [method, ln_a] : f.ln_a) {
      t["ln_a"][method] = ln_a;
      if (f.has_fast) t["fast_speedup"][method] = std::exp(ln_a - f.fast_ln_a);
    }
    j["mesh_shared_k"] = t;
  }
  out << j.dump(1) << "\n";
}

}  // namespace hinge::io
