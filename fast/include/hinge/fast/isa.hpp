// hinge/fast/isa.hpp: the instruction sets the double kernels are compiled for. Each hot double loop exists
// for the baseline x86-64, for x86-64-v3 (AVX2 with a hardware fused multiply-add) and, for the per-hinge
// kernel and the face pass, x86-64-v4 (AVX-512); the best the processor has is chosen at the first call,
// unless the environment variable HINGE_ISA (avx512, avx2, baseline; docs/contract.md) names one. Every
// version computes the same bits (lane-by-lane IEEE arithmetic, no contraction, exact fused multiply-adds).
#pragma once

#include <array>
#include <string_view>

#include "hinge/fast/hinge_kernel.hpp"

namespace hinge::fast {

enum class Isa { baseline, avx2, avx512 };

// "baseline", "avx2", "avx512".
std::string_view isa_name(Isa isa);
// Whether this processor runs code compiled for `isa`.
bool isa_available(Isa isa);

// The instruction set the double kernels use: the one HINGE_ISA names, or the best this processor has.
// Read once; throws std::invalid_argument "HINGE_ISA=...: ..." (at every call) when HINGE_ISA is not one of
// avx512, avx2, baseline, or names one this processor lacks.
Isa active_isa();

// The double per-hinge kernel compiled for `isa` (tests and benchmarks compare them): as
// hinge_derivatives<double>, and true; false, with nothing written, where the processor lacks `isa`.
bool hinge_derivatives(Isa isa, const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out);

}  // namespace hinge::fast
