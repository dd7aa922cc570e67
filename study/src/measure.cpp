// The study's and the benchmark's measuring tools (hinge/study/measure.hpp).
#include "hinge/study/measure.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>

namespace hinge::study {

double clock_ghz(int runs, double seconds) {
#if defined(__x86_64__) && defined(__GNUC__)
  const auto rounds = static_cast<std::uint64_t>(seconds * 1e9);  // four additions a round: ~0.25 ns at 4 GHz
  std::vector<double> ghz;
  for (int r = 0; r < runs; ++r) {
    std::uint64_t x = 0, one = 1;
    const auto start = std::chrono::steady_clock::now();
    // Register operands: some processors (Intel's Golden Cove cores among them) execute a chain of
    // additions of an immediate faster than one a cycle, which would read as 6-8 GHz.
    for (std::uint64_t i = 0; i < rounds; ++i)
      asm volatile("add %1, %0\n\tadd %1, %0\n\tadd %1, %0\n\tadd %1, %0" : "+r"(x) : "r"(one));
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ghz.push_back(4e-9 * double(rounds) / s);
  }
  std::sort(ghz.begin(), ghz.end());
  return ghz[ghz.size() / 2];
#else
  (void)runs, (void)seconds;
  return 0;
#endif
}

PowerLaw fit_power_law(const std::vector<std::pair<double, double>>& points) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const auto& [n, t] : points) {
    const double x = std::log(n), y = std::log(t);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double m = static_cast<double>(points.size());
  PowerLaw p;
  p.k = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  p.ln_a = (sy - p.k * sx) / m;
  return p;
}

double fit_ln_a(const std::vector<std::pair<double, double>>& points, double k) {
  double sum = 0;
  for (const auto& [n, t] : points) sum += std::log(t) - k * std::log(n);
  return sum / static_cast<double>(points.size());
}

}  // namespace hinge::study
