// Checks that the tsan preset's ThreadSanitizer really runs: a deliberate data race (two threads
// incrementing one plain int) must be reported and end the process (TSAN_OPTIONS halt_on_error=1 in the
// test preset; the report's exit status is 66). Built only with HINGE_SANITIZE_THREAD, part of the tsan
// build's targets, so the pass over the threaded tests cannot be silently uninstrumented.
#include <gtest/gtest.h>

#include <cstdlib>
#include <thread>

#if !defined(__SANITIZE_THREAD__)
#error "thread_sanitizer_test.cpp is built only with HINGE_SANITIZE_THREAD"
#endif

namespace {

int shared_counter = 0;  // deliberately not atomic

void increment_many() {
  for (int i = 0; i < 100000; ++i) shared_counter = shared_counter + 1;
}

[[noreturn]] void race() {
  std::thread a(increment_many);
  std::thread b(increment_many);
  a.join();
  b.join();
  std::exit(0);  // reached only if the race went unreported
}

TEST(ThreadSanitizer, ReportsADataRace) { EXPECT_EXIT(race(), testing::ExitedWithCode(66), "data race"); }

}  // namespace
