// The library's exceptions (hinge/core/errors.hpp).
#include "hinge/core/errors.hpp"

namespace hinge {

void throw_outside_double(const std::string& what) { throw DomainError(what + " is outside the range of double"); }
void throw_outside_float(const std::string& what) {
  throw DomainError(what + " overflowed in float (the value, or a step towards it, is outside float's range)");
}

}  // namespace hinge
