// The floating-point environment check (hinge/core/fp_environment.hpp).
#include "hinge/core/fp_environment.hpp"

#include <cfenv>
#include <string>

#include "hinge/core/errors.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif

namespace hinge {

namespace {

// The rounding-control field's meaning (the same two bits in the SSE and the x87 control registers, and
// the order of FE_TONEAREST, FE_DOWNWARD, FE_UPWARD, FE_TOWARDZERO on x86).
const char* rounding_name(unsigned field) {
  switch (field) {
    case 1: return "downward";
    case 2: return "upward";
    case 3: return "toward zero";
    default: return "to nearest";
  }
}

}  // namespace

void check_fp_environment() {
  std::string wrong;
  const auto add = [&](const std::string& what) { wrong += (wrong.empty() ? "" : "; ") + what; };
#if defined(__x86_64__) || defined(__i386__)
  // fegetround reads the x87 control word only; double arithmetic follows the SSE register (MXCSR).
  const unsigned csr = _mm_getcsr();
  if ((csr >> 13) & 3u) add(std::string("rounding is ") + rounding_name((csr >> 13) & 3u) + " (MXCSR)");
  if (csr & 0x8000u) add("flush-to-zero is set (MXCSR bit 15)");
  if (csr & 0x0040u) add("denormals-are-zero is set (MXCSR bit 6)");
  unsigned short x87 = 0;
  __asm__("fnstcw %0" : "=m"(x87));
  if ((x87 >> 10) & 3u) add(std::string("rounding is ") + rounding_name((x87 >> 10) & 3u) + " (x87, long double)");
  if (((x87 >> 8) & 3u) != 3u) add("the x87 precision control is below 64 bits (long double)");
#else
  if (std::fegetround() != FE_TONEAREST) add("rounding is not to nearest");
#endif
  if (!wrong.empty())
    throw EnvironmentError("the floating-point environment breaks exact arithmetic: " + wrong +
                           ". hinge needs rounding to nearest with subnormals kept (fesetenv(FE_DFL_ENV) restores it)");
}

}  // namespace hinge
