// hinge/core/fp_environment.hpp: the floating-point environment the library's exact steps need.
// The exact predicates, the error-free products and sums of the fast kernel and the power-of-two
// rescaling are exact only with rounding to nearest and with subnormal numbers kept. A host application
// can change both for its own threads (fesetround; the SSE control register's flush-to-zero and
// denormals-are-zero bits, set by -ffast-math's start-up code or by hand; the x87 precision control,
// which long double depends on): the results would then be wrong in their last bits, or in every bit on
// hinges near the ends of the exponent range, without any sign. The entry points (reference::
// theta_derivatives and assemble, fast::hinge_derivatives and Assembler::evaluate, hence the C ABI and
// the plugins) check the calling thread's environment first and throw instead.
#pragma once

namespace hinge {

// Throws hinge::EnvironmentError naming every setting that differs from what exact arithmetic needs
// (rounding other than to nearest; flush-to-zero; denormals-are-zero; x87 precision below 64 bits).
// About 5 ns here (two control-register reads): 2% of one fast::hinge_derivatives call, once per call
// of the span form and of a mesh evaluation.
void check_fp_environment();

}  // namespace hinge
