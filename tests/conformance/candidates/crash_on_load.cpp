// A plugin that crashes while it is being loaded (its constructor raises SIGSEGV): hinge conform survives
// it too and reports the plugin as unusable (exit status 2).
#include <csignal>

#include "hinge/candidate.h"

__attribute__((constructor)) static void crash_on_load() { std::raise(SIGSEGV); }

extern "C" HINGE_CANDIDATE_EXPORT int hinge_candidate(const double*, double*, double*, double*) { return 1; }
