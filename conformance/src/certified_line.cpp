// A certified result as a line of `hinge oracle` (hinge/conformance/certified_line.hpp).
#include "hinge/conformance/certified_line.hpp"

#include <nlohmann/json.hpp>

#include "hinge/io/jsonl.hpp"

namespace hinge::conformance {

std::string certified_line(const std::string& id_json, const oracle::CertifiedTheta& c, bool report_precision) {
  RoundedTheta r;
  r.theta = c.theta;
  r.grad = c.grad;
  r.hess = c.hess;
  std::string line = io::result_line(id_json, r);
  line.pop_back();  // '}'
  if (report_precision)
    line += std::string(", \"path\": \"") + oracle::path_name(c.path) + "\", \"bits\": " + std::to_string(c.bits) +
            ", \"exact_bits\": " + std::to_string(c.exact_bits) + ", \"ties\": " + std::to_string(c.ties) +
            ", \"decided_exactly\": " + std::to_string(c.decided_exactly);
  if (!c.uncertified.empty()) {
    nlohmann::json flags = nlohmann::json::array();
    for (const auto& u : c.uncertified) flags.push_back({{"output", u.output}, {"enclosure", {u.lower, u.upper}}});
    line += ", \"uncertified\": " + flags.dump();
  }
  line += '}';
  return line;
}

}  // namespace hinge::conformance
