// hinge/fast/isa.hpp: the instruction sets the double kernels are compiled for. Each hot double loop exists
// for the baseline x86-64, for x86-64-v3 (AVX2 with a hardware fused multiply-add) and, for the per-hinge
// kernel, x86-64-v4 (AVX-512); the best the processor has is chosen at the first call. Every version
// computes the same bits (lane-by-lane IEEE arithmetic, no contraction, exact fused multiply-adds).
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

// The double per-hinge kernel compiled for `isa` (tests and benchmarks compare them): as
// hinge_derivatives<double>, and true; false, with nothing written, where the processor lacks `isa`.
bool hinge_derivatives(Isa isa, const std::array<double, 12>& x, bool want_hessian, HingeDerivatives<double>& out);

}  // namespace hinge::fast
