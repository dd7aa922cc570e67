// energy_answer IN OUT [--no-probes]: an outside program answering `hinge conform --energy E --inputs` (the file
// route of docs/energy-conformance-cli.md): reads the lines {"id", "category", "x", "rest"} of IN, evaluates the
// bending term of candidates/energy_term.hpp (the tan energy, the contract's weight, k = 1) on each, and writes
// {"id", "energy", "grad", "hess"} (or {"id", "error"}) to OUT, for `hinge conform --energy tan --candidate OUT`.
// --no-probes leaves out the consistency probes' lines (category "consistency"), as a program that answers the
// graded pairs alone would. Exit status 0, or 2 for a usage error or an unreadable line.
#include <cstring>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

#include "candidates/energy_term.hpp"
#include "hinge/io/energy_lines.hpp"

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4 || (argc == 4 && std::strcmp(argv[3], "--no-probes") != 0)) {
    std::cerr << "usage: energy_answer IN OUT [--no-probes]\n";
    return 2;
  }
  const bool probes = argc == 3;
  std::ifstream in(argv[1]);
  std::ofstream out(argv[2]);
  if (!in || !out) {
    std::cerr << "energy_answer: cannot open " << argv[1] << " or " << argv[2] << "\n";
    return 2;
  }
  std::string text;
  for (long line = 1; std::getline(in, text); ++line) {
    try {
      const nlohmann::json j = nlohmann::json::parse(text);
      if (!probes && j.at("category").get<std::string>() == "consistency") continue;
      double x[12], rest[12];
      for (int i = 0; i < 12; ++i) {
        x[i] = j.at("x").at(i).get<double>();
        rest[i] = j.at("rest").at(i).get<double>();
      }
      hinge::io::EnergyOutput r;
      if (candidates::tan_term(x, rest, 1.0, &r.theta, r.grad.data(), r.hess.data())) {
        r.status = hinge::io::EnergyOutput::Status::ok;
        hinge::io::check_finite(r);
      } else {
        r.status = hinge::io::EnergyOutput::Status::error;
        r.error = "cannot evaluate";
      }
      out << hinge::io::energy_output_line(j.at("id").get<std::string>(), r) << '\n';
    } catch (const nlohmann::json::exception& e) {
      std::cerr << "energy_answer: " << argv[1] << ":" << line << ": " << e.what() << "\n";
      return 2;
    }
  }
  out.flush();
  return out ? 0 : 2;
}
