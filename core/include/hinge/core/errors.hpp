// hinge/core/errors.hpp: the exceptions the library throws. Every message names what is wrong and
// where (file and line, face, edge or hinge), so that a command can print it as it is.
#pragma once

#include <stdexcept>
#include <string>

namespace hinge {

// Input that cannot be evaluated: an unreadable or malformed file, a non-manifold or inconsistently
// oriented mesh, a degenerate triangle or hinge, a non-finite coordinate.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Input that is valid but whose result cannot be given: an energy that is infinite at the current
// angle (tan at theta = +-pi), or an exact result outside the range of the output type.
class DomainError : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

// The calling thread's floating-point environment is not the one exact arithmetic needs (rounding to
// nearest, subnormals kept; hinge/core/fp_environment.hpp). The message says which setting differs.
class EnvironmentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// DomainError "<what> is outside the range of double" (what: "theta", "the gradient", "the Hessian", "the
// energy"): an exact result, or one computed in a wider type, that no finite double can hold.
[[noreturn]] void throw_outside_double(const std::string& what);
// DomainError "<what> overflowed in float (...)": a result computed in float that overflowed there
// (`hinge eval --scalar float`): the value itself, or a step towards it, is outside float's range.
[[noreturn]] void throw_outside_float(const std::string& what);

}  // namespace hinge
