// Checks that the sanitizer flags of the asan-ubsan preset really reach the compiler: AddressSanitizer
// defines __SANITIZE_ADDRESS__, and UndefinedBehaviorSanitizer with -fno-sanitize-recover turns signed
// overflow into an abort. Built only when HINGE_SANITIZE is on.
#include <gtest/gtest.h>

#include <limits>

#ifndef HINGE_SANITIZED
#error "sanitizers_test.cpp is built only with HINGE_SANITIZE"
#endif

TEST(Sanitizers, AddressSanitizerIsCompiledIn) {
#ifdef __SANITIZE_ADDRESS__
  SUCCEED();
#else
  FAIL() << "-fsanitize=address did not reach the compiler";
#endif
}

int overflow(int x) {
  volatile int y = x;  // keeps the addition at run time
  return y + 1;
}

TEST(Sanitizers, UndefinedBehaviorAborts) {
  EXPECT_DEATH(
      {
        volatile int result = overflow(std::numeric_limits<int>::max());  // used, so not optimized away
        (void)result;
      },
      "overflow");
}
