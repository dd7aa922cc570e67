// hinge/core/method.hpp: the evaluation methods by name (docs/contract.md: `hinge eval --method`, `hinge
// hessian --method`, a scene's `effects.bending.method`, the study's rows, the Python module). The names
// are part of the problem's description; hinge::methods (methods/) evaluates them.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace hinge {

enum class Method {
  reference,  // hinge::reference: eqs. (4)-(6) transcribed (mesh: hinge by hinge)
  fast,       // hinge::fast: the lean per-hinge kernel (mesh: Algorithm 2)
  autodiff,   // hinge::baselines: Eigen's AutoDiff on the atan2 definition (mesh: hinge by hinge, as reference)
  symbolic,   // hinge::baselines: SymPy-generated code from the atan2 definition (mesh: as reference)
};

// "reference", "fast", "autodiff", "symbolic".
std::string_view method_name(Method method);
// The names, in the order above.
std::vector<std::string> method_names();
// Throws std::invalid_argument "unknown method 'X': expected one of reference, fast, autodiff, symbolic".
Method parse_method(std::string_view name);

}  // namespace hinge
