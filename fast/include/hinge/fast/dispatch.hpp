// hinge/fast/dispatch.hpp: hot double loops are compiled twice, for the baseline x86-64 and for
// x86-64-v3 (AVX2 and a hardware fused multiply-add, which the error-free transformations of exact.hpp
// use at every step), and the second is chosen at run time where the processor has it. Both versions
// compute the same bits: the build disables contraction (-ffp-contract=off) and std::fma is exact in
// either. Elsewhere (other compilers or processors) there is one version.
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define HINGE_FAST_TARGET_V3 __attribute__((target("arch=x86-64-v3")))
namespace hinge::fast::detail {
inline bool has_x86_64_v3() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
}
}  // namespace hinge::fast::detail
#else
#define HINGE_FAST_TARGET_V3
namespace hinge::fast::detail {
inline bool has_x86_64_v3() { return false; }
}  // namespace hinge::fast::detail
#endif
