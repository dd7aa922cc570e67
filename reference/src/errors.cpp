// The library's exceptions (hinge/reference/errors.hpp).
#include "hinge/reference/errors.hpp"

namespace hinge {

void throw_outside_double(const std::string& what) { throw DomainError(what + " is outside the range of double"); }

}  // namespace hinge
