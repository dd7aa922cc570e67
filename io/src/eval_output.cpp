// Reading `hinge eval` output lines (hinge/io/eval_output.hpp).
#include "hinge/io/eval_output.hpp"

#include <cctype>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

#include "hinge/core/errors.hpp"
#include "hinge/io/jsonl.hpp"

namespace hinge::io {
namespace {

using Status = EvalOutput::Status;

EvalOutput parse_result(const nlohmann::json& j) {
  EvalOutput r;
  if (auto e = j.find("error"); e != j.end()) {
    r.status = Status::error;
    r.error = e->is_string() ? e->get<std::string>() : e->dump();
    return r;
  }
  // A number, or what a candidate's JSON writer makes of a NaN or an infinity: null (nlohmann, JavaScript)
  // and "NaN" are NaN; "Infinity", "-Infinity", "inf", "-inf" infinities; anything else NaN.
  auto number = [](const nlohmann::json& v, double& out) {
    if (v.is_number()) {
      out = v.get<double>();
      return;
    }
    const std::string text = v.is_string() ? v.get<std::string>() : "";
    const bool infinite = text == "Infinity" || text == "inf" || text == "-Infinity" || text == "-inf";
    out = !infinite ? std::numeric_limits<double>::quiet_NaN() : text[0] == '-' ? -HUGE_VAL : HUGE_VAL;
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
  check_finite(r);
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

}  // namespace

void check_finite(EvalOutput& r) {
  if (r.status != Status::ok) return;
  bool nan = std::isnan(r.theta), finite = std::isfinite(r.theta);
  for (double v : r.grad) nan = nan || std::isnan(v), finite = finite && std::isfinite(v);
  for (double v : r.hess) nan = nan || std::isnan(v), finite = finite && std::isfinite(v);
  if (nan) {
    r.status = Status::missing;
    r.error = "a NaN in the outputs";
  } else if (!finite) {
    r.status = Status::nonfinite;
    r.error = "an infinity in the outputs";
  }
}

std::map<std::string, EvalOutput> read_eval_outputs(std::istream& in, const std::string& name) {
  std::map<std::string, EvalOutput> results;
  std::string text;
  for (long number = 1; std::getline(in, text); ++number) {
    if (blank(text)) continue;
    std::string id;
    EvalOutput r;
    try {
      const nlohmann::json j = nlohmann::json::parse(text);
      if (!j.is_object() || !j.contains("id") || !j["id"].is_string())
        throw InputError(name + ":" + std::to_string(number) + ": not an object with a string \"id\"");
      id = j["id"].get<std::string>();
      r = parse_result(j);
    } catch (const nlohmann::json::exception&) {
      const std::optional<std::string> quoted = quoted_id(text);
      std::optional<std::string> parsed;
      if (quoted) {
        try {
          parsed = nlohmann::json::parse(*quoted).get<std::string>();
        } catch (const nlohmann::json::exception&) {  // an id with a bad escape
        }
      }
      if (!parsed) throw InputError(name + ":" + std::to_string(number) + ": not valid JSON, and no \"id\" found");
      id = *parsed;
      // Not JSON: a NaN or an infinity written as a bare token, as many writers do. A NaN makes the result
      // not evaluated (missing), an infinity alone non-finite.
      const bool nan = text.find("NaN") != std::string::npos || text.find("nan") != std::string::npos;
      r.status = nan ? Status::missing : Status::nonfinite;
      r.error = nan ? "a NaN in the outputs" : "an infinity in the outputs";
    }
    results.emplace(id, std::move(r));  // the first line of an id counts
  }
  if (in.bad()) throw InputError("reading candidate " + name + " failed");
  return results;
}

std::map<std::string, EvalOutput> read_eval_outputs(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read candidate " + path);
  return read_eval_outputs(in, path);
}

std::string eval_output_line(const std::string& id, const EvalOutput& r) {
  const std::string id_json = json_string(id);
  if (r.status == Status::error || r.status == Status::missing)
    return error_line(id_json, r.error.empty() ? "cannot evaluate" : r.error);
  if (r.status == Status::nonfinite) return error_line(id_json, "non-finite result");
  RoundedTheta v;
  v.theta = r.theta;
  v.grad = r.grad;
  v.hess = r.hess;
  return result_line(id_json, v);
}

}  // namespace hinge::io
