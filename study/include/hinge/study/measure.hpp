// hinge/study/measure.hpp: the measuring tools the study and the benchmark (bench/) share: the processor's
// clock (so that times can be given in cycles too), and the power law t = a n^k fitted in log-log (the
// paper's section 7.3, Table 2).
#pragma once

#include <utility>
#include <vector>

namespace hinge::study {

// The processor's clock in GHz, as a chain of dependent one-cycle additions of registers measures it: the
// median of `runs` runs of about `seconds` each (x86-64 with GCC or Clang; 0 elsewhere). Hosts' clocks
// move from hour to hour (here between about 2.7 and 4.3 GHz), and every time in ns with them: cycles
// compare across runs, ns do not.
double clock_ghz(int runs = 5, double seconds = 0.1);

// ln t = k ln n + ln a by least squares over the points (n, t) (the paper's g(ln x) = k ln x + ln a).
struct PowerLaw {
  double k = 0, ln_a = 0;
};
PowerLaw fit_power_law(const std::vector<std::pair<double, double>>& points);
// ln a for a given k (the paper re-estimates ln a of every method with the k they share).
double fit_ln_a(const std::vector<std::pair<double, double>>& points, double k);

}  // namespace hinge::study
