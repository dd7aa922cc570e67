// tests/fuzz/fuzz_target.hpp: what every fuzz target here shares. A target feeds the bytes to one reader
// of hinge::io and checks what the contract promises for any input: the reader returns a well-formed
// result or throws hinge::InputError; anything else (another exception, a crash, a sanitizer report, a
// result that breaks an invariant) is a defect. libFuzzer calls LLVMFuzzerTestOneInput (the `fuzz`
// preset); replay_main.cpp calls it on the committed corpus in the ordinary builds (ctest label `fuzz`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace hinge::fuzz {

// Stops the run with `why` when an invariant fails (libFuzzer records the input that did it).
inline void require(bool ok, const char* why) {
  if (!ok) {
    std::fprintf(stderr, "fuzz invariant broken: %s\n", why);
    std::abort();
  }
}

inline std::string as_string(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace hinge::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
