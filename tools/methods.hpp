// tools/methods.hpp: the evaluation methods a command can name (--method), hinge by hinge and mesh-wide.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hinge/reference/rounded.hpp"

namespace hinge::tools {

// Evaluates one hinge with `method` ("reference", "fast") in `scalar`, rounded to double. Throws
// hinge::InputError / hinge::DomainError for the hinge, std::invalid_argument for an unknown method.
reference::RoundedTheta evaluate_hinge(const std::string& method, const ScalarType& scalar,
                                       const std::array<double, 12>& x);

struct MeshJob {
  const Mesh* deformed = nullptr;
  const Mesh* rest = nullptr;
  const Topology* topology = nullptr;
  reference::EnergyParameters parameters;
  unsigned request = reference::want_all;
  int threads = 1;
};
reference::RoundedMesh evaluate_mesh(const std::string& method, const ScalarType& scalar, const MeshJob& job);

// The names --method accepts; require_method throws std::invalid_argument for any other.
std::vector<std::string> method_names();
void require_method(const std::string& method);

}  // namespace hinge::tools
