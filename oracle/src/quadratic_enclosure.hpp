// oracle/src/quadratic_enclosure.hpp (private to hinge::oracle): the isometric bending term of one hinge
// enclosed at the current working precision (quadratic.hpp), for its certification (quadratic.cpp) and its
// condition numbers (conditioning.cpp).
#pragma once

#include "hinge/oracle/exact.hpp"
#include "hinge_energy.hpp"

namespace hinge::oracle::detail {

// psi, its gradient and Hessian (row-major) of the deformed hinge `x` with the rest hinge `rest` (exact
// integers), exact zeros kept exact (quadratic.hpp). `rest_form`: exact_hinge(rest, false).
HingeEnergy quadratic_enclosure(const ScaledHinge& x, const ScaledHinge& rest, const ExactHinge& rest_form,
                                const Interval& k);

}  // namespace hinge::oracle::detail
