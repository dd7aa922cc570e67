// The methods behind --method (tools/methods.hpp).
#include "methods.hpp"

#include <stdexcept>

#include "hinge/fast/rounded.hpp"

namespace hinge::tools {

// "fast": hinge::fast (the per-hinge kernel for hinges, Algorithm 2 for meshes), in every scalar type
// the reference has (float, double, long-double, float128, bin128, mpfr:BITS).
std::vector<std::string> method_names() { return {"reference", "fast"}; }

void require_method(const std::string& method) {
  std::string known;
  for (const auto& m : method_names()) {
    if (m == method) return;
    known += (known.empty() ? "" : ", ") + m;
  }
  throw std::invalid_argument("unknown method '" + method + "': expected one of " + known);
}

reference::RoundedTheta evaluate_hinge(const std::string& method, const ScalarType& scalar,
                                       const std::array<double, 12>& x) {
  require_method(method);
  if (method == "fast") return fast::hinge_derivatives_rounded(scalar, x);
  return reference::theta_derivatives_rounded(scalar, x);
}

reference::RoundedMesh evaluate_mesh(const std::string& method, const ScalarType& scalar, const MeshJob& job) {
  require_method(method);
  if (method == "fast")
    return fast::assemble_rounded(scalar, *job.deformed, *job.rest, *job.topology, job.parameters, job.request,
                                  job.threads);
  return reference::assemble_rounded(scalar, *job.deformed, *job.rest, *job.topology, job.parameters, job.request);
}

}  // namespace hinge::tools
