// Explicit instantiations of hinge::fast for mpfr (run-time precision).
#include "hinge/fast/assemble.hpp"
#include "hinge/fast/hinge_kernel.hpp"

namespace hinge::fast {

template HingeDerivatives<mpfr> hinge_derivatives<mpfr>(const std::array<double, 12>&, bool);

template class Assembler<mpfr>;

}  // namespace hinge::fast
