# hinge::warnings: an interface target carrying the project's warning flags.
add_library(hinge_warnings INTERFACE)
add_library(hinge::warnings ALIAS hinge_warnings)
target_compile_options(hinge_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  $<$<AND:$<CXX_COMPILER_ID:GNU,Clang>,$<BOOL:${HINGE_WARNINGS_AS_ERRORS}>>:-Werror>)

# HINGE_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer on every target, errors fatal. The test
# `sanitizers` (label sanitizers) checks that the flags reached the compiler.
option(HINGE_SANITIZE "Build with -fsanitize=address,undefined -fno-sanitize-recover=all" OFF)
if(HINGE_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  add_compile_definitions(HINGE_SANITIZED=1)
endif()

# HINGE_SANITIZE_THREAD: ThreadSanitizer (the tsan preset: the threaded tests only, docs/testing.md).
option(HINGE_SANITIZE_THREAD "Build with -fsanitize=thread" OFF)
if(HINGE_SANITIZE_THREAD)
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
endif()
