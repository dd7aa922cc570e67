// Explicit instantiations of hinge::fast for float and double (double's per-hinge kernel: see
// hinge_kernel_double.cpp). One unit per scalar family keeps builds short on two cores.
#include "hinge/fast/assemble.hpp"
#include "hinge/fast/hinge_kernel.hpp"

namespace hinge::fast {

template HingeDerivatives<float> hinge_derivatives<float>(const std::array<double, 12>&, bool);
template HingeDerivatives<double> hinge_derivatives<double>(const std::array<double, 12>&, bool);

template class Assembler<float>;
template class Assembler<double>;

}  // namespace hinge::fast
