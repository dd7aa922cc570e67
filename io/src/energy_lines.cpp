// The files of the command-line energy conformance (hinge/io/energy_lines.hpp).
#include "hinge/io/energy_lines.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hinge/core/errors.hpp"
#include "hinge/io/jsonl.hpp"
#include "hinge/io/number.hpp"

namespace hinge::io {

std::string energy_input_line(const std::string& id, const std::string& category, const std::array<double, 12>& x,
                              const std::array<double, 12>& rest) {
  std::string line = "{\"id\": ";
  line += json_string(id);
  line += ", \"category\": ";
  line += json_string(category);
  line += ", \"x\": ";
  append_array(line, x.data(), 12);
  line += ", \"rest\": ";
  append_array(line, rest.data(), 12);
  line += "}";
  return line;
}

std::map<std::string, EnergyOutput> read_energy_outputs(std::istream& in, const std::string& name) {
  // Each line rewritten as the `hinge eval` line it stands for ("energy" renamed "theta", a "theta" dropped),
  // line for line so that the line numbers of errors stay, then read by read_eval_outputs: one set of rules
  // for a candidate's NaNs, nulls, infinities, missing arrays and lines that are not JSON. A line that is not
  // a JSON object, or is an error line, goes as it is.
  std::stringstream eval;
  std::string text;
  while (std::getline(in, text)) {
    nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!j.is_discarded() && j.is_object() && !j.contains("error")) {
      j.erase("theta");
      if (auto e = j.find("energy"); e != j.end()) {
        nlohmann::json energy = std::move(*e);
        j.erase("energy");
        j["theta"] = std::move(energy);
      }
      text = j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    }
    eval << text << '\n';
  }
  if (in.bad()) throw InputError("reading candidate " + name + " failed");
  std::map<std::string, EnergyOutput> results = read_eval_outputs(eval, name);
  for (auto& [id, r] : results)
    if (r.status == EnergyOutput::Status::missing && r.error == "no \"theta\"") r.error = "no \"energy\"";
  return results;
}

std::map<std::string, EnergyOutput> read_energy_outputs(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read candidate " + path);
  return read_energy_outputs(in, path);
}

std::string energy_output_line(const std::string& id, const EnergyOutput& r) {
  const std::string id_json = json_string(id);
  if (r.status == EnergyOutput::Status::error || r.status == EnergyOutput::Status::missing)
    return error_line(id_json, r.error.empty() ? "cannot evaluate" : r.error);
  if (r.status == EnergyOutput::Status::nonfinite) return error_line(id_json, "non-finite result");
  std::string out;
  out.reserve(4096);
  out += "{\"id\": ";
  out += id_json;
  out += ", \"energy\": ";
  append_double(out, r.theta);
  out += ", \"grad\": ";
  append_array(out, r.grad.data(), r.grad.size());
  out += ", \"hess\": ";
  append_array(out, r.hess.data(), r.hess.size());
  out += '}';
  return out;
}

}  // namespace hinge::io
