// hinge/io/energy_lines.hpp: the files of the conformance of bending energies from the command line
// (`hinge conform --energy E`, docs/energy-conformance-cli.md), one JSON object per line:
//   inputs   {"id", "category", "x": [12], "rest": [12]}: a deformed hinge and its rest hinge, the contract's
//            order x0.x, x0.y, x0.z, x1.x, ..., x3.z (`--inputs` writes them)
//   outputs  {"id", "energy", "grad": [12], "hess": [144]} (hess row-major), or {"id", "error"} (`--candidate`
//            reads them; `--plugin --save` writes them)
// An output line is a line of `hinge eval` output with "energy" in the place of "theta", and is read by the
// same rules (eval_output.hpp): lenient where a candidate's numbers are bad (NaN, null, "NaN": missing; an
// infinity alone: non-finite; a missing array: missing), strict where the file is unusable (no readable id).
#pragma once

#include <array>
#include <iosfwd>
#include <map>
#include <string>

#include "hinge/io/eval_output.hpp"

namespace hinge::io {

// One output line: psi in the theta slot (as the energy conformance grades it).
using EnergyOutput = EvalOutput;

// An input line (without the newline).
std::string energy_input_line(const std::string& id, const std::string& category, const std::array<double, 12>& x,
                              const std::array<double, 12>& rest);

// The results of a file by id (the first line of an id counts), read as read_eval_outputs reads `hinge eval`
// output; a line without "energy" is missing ("no \"energy\""), a "theta" is ignored. Throws hinge::InputError
// "FILE:LINE: why" when a line has no readable id, or the file cannot be read.
std::map<std::string, EnergyOutput> read_energy_outputs(const std::string& path);
std::map<std::string, EnergyOutput> read_energy_outputs(std::istream& in, const std::string& name_for_errors);

// `r` as an output line (without the newline): an error line for anything not ok.
std::string energy_output_line(const std::string& id, const EnergyOutput& r);

}  // namespace hinge::io
