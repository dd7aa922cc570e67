// tests/support/fp_environment.hpp: changing the calling thread's floating-point environment as a host
// application might (hinge/core/fp_environment.hpp), and restoring the default at scope exit.
#pragma once

#include <cfenv>
#include <xmmintrin.h>

namespace hinge::test {

enum class Setting {
  flush_to_zero,
  denormals_are_zero,
  round_upward_sse,
  round_toward_zero_everywhere,
  x87_double_precision
};

class ScopedFpEnvironment {
 public:
  explicit ScopedFpEnvironment(Setting s) {
    switch (s) {
      case Setting::flush_to_zero: _mm_setcsr(_mm_getcsr() | 0x8000u); break;
      case Setting::denormals_are_zero: _mm_setcsr(_mm_getcsr() | 0x0040u); break;
      case Setting::round_upward_sse: _mm_setcsr((_mm_getcsr() & ~0x6000u) | 0x4000u); break;  // MXCSR only
      case Setting::round_toward_zero_everywhere: std::fesetround(FE_TOWARDZERO); break;
      case Setting::x87_double_precision: {
        unsigned short cw = 0;
        __asm__("fnstcw %0" : "=m"(cw));
        cw = static_cast<unsigned short>((cw & ~0x0300u) | 0x0200u);  // precision control: 53 bits
        __asm__ volatile("fldcw %0" : : "m"(cw));
        break;
      }
    }
  }
  ~ScopedFpEnvironment() { std::fesetenv(FE_DFL_ENV); }
  ScopedFpEnvironment(const ScopedFpEnvironment&) = delete;
  ScopedFpEnvironment& operator=(const ScopedFpEnvironment&) = delete;
};

inline constexpr Setting kAllSettings[] = {Setting::flush_to_zero, Setting::denormals_are_zero,
                                           Setting::round_upward_sse, Setting::round_toward_zero_everywhere,
                                           Setting::x87_double_precision};

}  // namespace hinge::test
