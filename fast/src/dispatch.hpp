// fast/src/dispatch.hpp: hot double loops are compiled more than once, for the baseline x86-64, for
// x86-64-v3 (AVX2 and a hardware fused multiply-add, which the error-free transformations of exact.hpp
// use at every step) and, for the per-hinge kernel, x86-64-v4 (AVX-512), and the best the processor has
// is chosen at run time. All versions compute the same bits: the build disables contraction
// (-ffp-contract=off), every operation is lane-by-lane IEEE arithmetic, and std::fma is exact in each.
// Elsewhere (other compilers or processors) there is one version.
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define HINGE_FAST_TARGET_V3 __attribute__((target("arch=x86-64-v3")))
#define HINGE_FAST_TARGET_V4 __attribute__((target("arch=x86-64-v4,prefer-vector-width=512")))
namespace hinge::fast::detail {
inline bool has_x86_64_v3() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2");
}
inline bool has_x86_64_v4() {
  __builtin_cpu_init();
  return has_x86_64_v3() && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
         __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512cd");
}
}  // namespace hinge::fast::detail
#else
#define HINGE_FAST_TARGET_V3
#define HINGE_FAST_TARGET_V4
namespace hinge::fast::detail {
inline bool has_x86_64_v3() { return false; }
inline bool has_x86_64_v4() { return false; }
}  // namespace hinge::fast::detail
#endif
