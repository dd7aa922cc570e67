// hinge/conformance/plugin.hpp: a candidate implementation loaded from a shared library (hinge/candidate.h), as
// `hinge conform --plugin LIB.so [--symbol NAME]` calls it: once per conformance case, from one thread. Two
// kinds: a bend angle (hinge_candidate_fn) and a bending term (hinge_energy_candidate_fn, `hinge conform
// --energy E --plugin`: once per graded pair and once per consistency probe).
//
// The library is loaded and called in a child process (docs/contract.md, "Plugins", version 2), so that
// hinge conform survives it: a case on which the plugin crashes, or runs longer than the time-out, fails
// with the signal or the time-out named, the child is started again, and the other cases still run. The
// child talks to the parent over a socket pair: a request's kind, then 12 doubles in (24 for a bending term: x,
// then the rest hinge), a status and 157 doubles out; or a batch to time (time()). Whatever the plugin prints goes to
// standard error.
#pragma once

#include <sys/types.h>

#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "hinge/candidate.h"
#include "hinge/conformance/grading.hpp"

namespace hinge::conformance {

// The plugin could not be loaded (no such file, no such symbol, a crash or a time-out while loading): a
// usage error of hinge conform (exit status 2).
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The function a plugin exports (hinge/candidate.h).
enum class PluginKind {
  theta,   // hinge_candidate_fn: theta, grad theta, Hess theta of a hinge x (default symbol hinge_candidate)
  energy,  // hinge_energy_candidate_fn: psi, grad psi, Hess psi of x with its rest hinge (hinge_energy_candidate)
};

class Plugin {
 public:
  // Starts the child, which loads `path` (dlopen) and finds `symbol` (dlsym), a function of `kind`; throws
  // PluginError naming both and the reason. `timeout_seconds` bounds each case, and the loading.
  Plugin(const std::string& path, const std::string& symbol, double timeout_seconds = 10,
         PluginKind kind = PluginKind::theta);
  ~Plugin();
  Plugin(const Plugin&) = delete;
  Plugin& operator=(const Plugin&) = delete;

  // The plugin's outputs for x: ok (or nonfinite, when it wrote a NaN or an infinity, or left an output
  // unwritten), or error: "returned N" when it returned nonzero, "crashed (signal N, NAME)" or "timed out
  // after S s" when the child did not survive the case (it is started again for the next one).
  // A theta plugin only (std::logic_error otherwise).
  CandidateResult operator()(const std::array<double, 12>& x);

  // The same for a bending term at x with its rest hinge: psi in the result's theta slot, as the energy
  // conformance grades it (energy_report.hpp). An energy plugin only (std::logic_error otherwise).
  CandidateResult operator()(const std::array<double, 12>& x, const std::array<double, 12>& rest);

  // The study's outside rows (docs/study.md, "Times"): the plugin timed in batches inside its own process.
  // Each of `rounds` rounds is a pass over `hinges`, one call per hinge writing into slot i of arrays the
  // child holds, and `repeats` passes of `beside` (a function of this program, which the child, its fork,
  // holds too: the kernel every row is compared with) over the same hinges into arrays of the same layout,
  // back to back, the two in alternating order. Per round, ns per hinge of the plugin and of `beside`; or
  // an error, as operator() names it ("returned N", a crash, a time-out after `timeout_seconds`), and no
  // rounds. A theta plugin only (std::logic_error otherwise).
  using PerHinge = void (*)(const double* x, double* theta, double* grad, double* hess);
  struct Timing {
    std::vector<std::array<double, 2>> rounds;  // {plugin, beside} ns per hinge
    std::string error;
  };
  Timing time(const std::vector<std::array<double, 12>>& hinges, int rounds, PerHinge beside, int repeats,
              double timeout_seconds);

  PluginKind kind() const { return kind_; }

  // Whether an error of operator() is one the plugin did not survive (a crash or a time-out).
  static bool fatal(const CandidateResult& r);

 private:
  void start();  // forks the child and waits for it to report the library loaded; throws PluginError
  void stop();   // kills and reaps the child, if any
  CandidateResult call(const double* in, std::size_t count);  // count doubles in, one answer out
  std::string path_, symbol_;
  double timeout_;
  PluginKind kind_;
  pid_t child_ = -1;
  int socket_ = -1;
};

}  // namespace hinge::conformance
