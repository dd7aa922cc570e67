// hinge/conformance/certified_line.hpp: a certified result as a line of `hinge oracle` (docs/contract.md): the
// result line of `hinge eval`, then the oracle's own fields. (The conformance kit owns it: it joins the
// oracle to the project's formats, hinge::io, which the oracle itself does not use.)
#pragma once

#include <string>

#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {

// {"id", "theta", "grad", "hess"} (without the newline), then with `report_precision` "path", "bits",
// "exact_bits", "ties", "decided_exactly", then, if any output could not be certified, "uncertified":
// [{"output", "enclosure": [lower, upper]}].
std::string certified_line(const std::string& id_json, const oracle::CertifiedTheta& c, bool report_precision);

}  // namespace hinge::conformance
