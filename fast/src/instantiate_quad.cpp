// Explicit instantiations of hinge::fast for long double, float128 and bin128.
#include "hinge/fast/assemble.hpp"
#include "hinge/fast/hinge_kernel.hpp"

namespace hinge::fast {

template HingeDerivatives<long double> hinge_derivatives<long double>(const std::array<double, 12>&, bool);
template HingeDerivatives<float128> hinge_derivatives<float128>(const std::array<double, 12>&, bool);
template HingeDerivatives<bin128> hinge_derivatives<bin128>(const std::array<double, 12>&, bool);

template class Assembler<long double>;
template class Assembler<float128>;
template class Assembler<bin128>;

}  // namespace hinge::fast
