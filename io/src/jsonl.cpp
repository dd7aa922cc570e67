// JSON Lines input and output of hinge eval / oracle (hinge/io/jsonl.hpp).
#include "hinge/io/jsonl.hpp"

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <string_view>

#include "hinge/io/number.hpp"

namespace hinge::io {

bool blank(const std::string& text) { return text.find_first_not_of(" \t\r\n\f\v") == std::string::npos; }

namespace {

// nlohmann::json rejects a whole line when one number overflows double (1e400), although the line is
// valid JSON whose hinge is merely non-finite input. Such numbers are replaced by the strings "inf" or
// "-inf", which parse_hinge_line turns into infinities (and the evaluation into a per-hinge error).
std::string mark_overflowing_numbers(const std::string& text) {
  std::string out;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (in_string) {
      out += c;
      if (c == '\\' && i + 1 < text.size()) out += text[++i];
      else if (c == '"') in_string = false;
      ++i;
    } else if (c == '"') {
      in_string = true;
      out += c;
      ++i;
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t end = i + 1;
      while (end < text.size() && std::string_view("0123456789+-.eE").find(text[end]) != std::string_view::npos) ++end;
      const std::string token = text.substr(i, end - i);
      const double value = std::strtod(token.c_str(), nullptr);
      out += std::isinf(value) ? (value > 0 ? "\"inf\"" : "\"-inf\"") : token;
      i = end;
    } else {
      out += c;
      ++i;
    }
  }
  return out;
}

}  // namespace

HingeLine parse_hinge_line(const std::string& text, long line_number) {
  HingeLine h;
  h.line = line_number;
  h.id_json = "null";
  nlohmann::json j;
  try {
    try {
      j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::out_of_range&) {  // a number outside the range of double
      j = nlohmann::json::parse(mark_overflowing_numbers(text));
    }
  } catch (const nlohmann::json::exception& e) {
    h.error = std::string("not valid JSON: ") + e.what();
    return h;
  }
  if (!j.is_object()) {
    h.error = "not a JSON object";
    return h;
  }
  if (auto id = j.find("id"); id != j.end()) h.id_json = id->dump();
  else {
    h.error = "missing \"id\"";
    return h;
  }
  if (auto c = j.find("category"); c != j.end() && c->is_string()) h.category = c->get<std::string>();
  auto x = j.find("x");
  if (x == j.end()) {
    h.error = "missing \"x\"";
    return h;
  }
  if (!x->is_array() || x->size() != 12) {
    h.error = "\"x\" must be an array of 12 numbers";
    return h;
  }
  std::array<double, 12> values;
  for (std::size_t i = 0; i < 12; ++i) {
    const auto& v = (*x)[i];
    if (v.is_string() && (v == "inf" || v == "-inf")) {  // from mark_overflowing_numbers
      values[i] = v == "inf" ? HUGE_VAL : -HUGE_VAL;
      continue;
    }
    if (!v.is_number()) {
      h.error = "\"x\"[" + std::to_string(i) + "] is not a number";
      return h;
    }
    values[i] = v.get<double>();  // integers convert exactly below 2^53, else correctly rounded
  }
  h.x = values;
  return h;
}

std::string result_line(const std::string& id_json, const RoundedTheta& r) {
  std::string out;
  out.reserve(4096);
  out += "{\"id\": " + id_json + ", \"theta\": ";
  append_double(out, r.theta);
  out += ", \"grad\": ";
  append_array(out, r.grad.data(), r.grad.size());
  out += ", \"hess\": ";
  append_array(out, r.hess.data(), r.hess.size());
  out += '}';
  return out;
}

std::string json_string(const std::string& s) {
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string result_line(const std::string& id_json, const RoundedTheta& r, const std::array<double, 3>& kappa) {
  std::string out = result_line(id_json, r);
  out.pop_back();  // '}'
  out += ", \"kappa\": {\"theta\": " + format_double(kappa[0]) + ", \"grad\": " + format_double(kappa[1]) +
         ", \"hess\": " + format_double(kappa[2]) + "}}";
  return out;
}

std::string input_line(const std::string& id, const std::string& category, const std::array<double, 12>& x) {
  std::string line = "{\"id\": " + json_string(id) + ", \"category\": " + json_string(category) + ", \"x\": ";
  append_array(line, x.data(), 12);
  line += "}";
  return line;
}

std::string error_line(const std::string& id_json, const std::string& error) {
  return "{\"id\": " + id_json + ", \"error\": " + json_string(error) + "}";
}

std::string invalid_line(const HingeLine& line) {
  return "{\"id\": " + line.id_json + ", \"line\": " + std::to_string(line.line) +
         ", \"error\": " + json_string(line.error) + "}";
}

}  // namespace hinge::io
