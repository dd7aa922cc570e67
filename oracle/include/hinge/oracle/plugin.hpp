// hinge/oracle/plugin.hpp: a candidate implementation loaded from a shared library (hinge/candidate.h), as
// `hinge conform --plugin LIB.so [--symbol NAME]` calls it: once per conformance case, from one thread.
#pragma once

#include <array>
#include <stdexcept>
#include <string>

#include "hinge/candidate.h"
#include "hinge/oracle/conformance.hpp"

namespace hinge::oracle::conformance {

// The plugin could not be loaded, or has no such symbol (a usage error of hinge conform: exit status 2).
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Plugin {
 public:
  // dlopen(path), dlsym(symbol); throws PluginError naming both and dlerror()'s reason.
  Plugin(const std::string& path, const std::string& symbol);
  ~Plugin();
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  // The plugin's outputs for x: ok (or nonfinite, when it wrote a NaN or an infinity, or left an output
  // unwritten), or error when it returned nonzero ("returned N").
  CandidateResult operator()(const std::array<double, 12>& x) const;

 private:
  void* handle_ = nullptr;
  hinge_candidate_fn* function_ = nullptr;
};

}  // namespace hinge::oracle::conformance
