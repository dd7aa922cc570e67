// Candidate implementations in shared libraries (hinge/oracle/plugin.hpp).
#include "hinge/oracle/plugin.hpp"

#include <dlfcn.h>

#include <limits>

namespace hinge::oracle::conformance {

Plugin::Plugin(const std::string& path, const std::string& symbol) {
  handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) throw PluginError("cannot load plugin " + path + ": " + dlerror());
  void* f = dlsym(handle_, symbol.c_str());
  if (!f) {
    const std::string why = dlerror();
    dlclose(handle_);
    throw PluginError("plugin " + path + " has no symbol " + symbol + ": " + why);
  }
  function_ = reinterpret_cast<hinge_candidate_fn*>(f);
}

Plugin::~Plugin() {
  if (handle_) dlclose(handle_);
}

CandidateResult Plugin::operator()(const std::array<double, 12>& x) const {
  CandidateResult r;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.theta = nan;  // what the plugin leaves unwritten counts as non-finite
  r.grad.fill(nan);
  r.hess.fill(nan);
  const int status = function_(x.data(), &r.theta, r.grad.data(), r.hess.data());
  if (status != 0) {
    r.status = CandidateResult::Status::error;
    r.error = "returned " + std::to_string(status);
    return r;
  }
  r.status = CandidateResult::Status::ok;
  io::check_finite(r);
  return r;
}

}  // namespace hinge::oracle::conformance
