// hinge demo: the main job on built-in defaults. Evaluates a built-in set of hinges (the worked examples
// of CONVENTIONS.md and random well-shaped hinges, rotated, scaled and offset) with the reference in
// double and with the oracle (MPFR, 256 bits), and prints a short summary: accuracy in units of 2^-53
// and time per hinge.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <random>

#include "commands.hpp"
#include "hinge/reference/evaluate.hpp"
#include "methods.hpp"
#include "output.hpp"

namespace hinge::tools {

namespace {

struct NamedHinge {
  std::string id;
  std::array<double, 12> x;
};

std::vector<NamedHinge> builtin_hinges(int random_count, unsigned seed) {
  std::vector<NamedHinge> hinges = {  // ../shared/spec/examples/eval-input.jsonl
      {"flat", {0.5, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.5, -1.0, 0.0}},
      {"valley", {0.5, 1.0, 0.25, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.25, -1.0, 0.5}},
      {"generic", {0.125, 0.75, -0.5, -0.25, 0.0625, 0.0, 1.0, 0.125, -0.0625, 0.625, -0.875, 0.375}}};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1, 1), decade(-3, 3);
  while (static_cast<int>(hinges.size()) < 3 + random_count) {
    std::array<double, 12> x;
    const double scale = std::pow(10.0, decade(rng)), offset = 100 * unit(rng);
    for (double& c : x) c = offset + scale * unit(rng);
    if (reference::well_shaped(x)) hinges.push_back({"random-" + std::to_string(hinges.size() - 3), x});
  }
  return hinges;
}

double normwise_error(const std::array<double, 144>& h, const std::array<double, 144>& exact) {
  long double diff = 0, norm = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    diff += (static_cast<long double>(h[i]) - exact[i]) * (static_cast<long double>(h[i]) - exact[i]);
    norm += static_cast<long double>(exact[i]) * exact[i];
  }
  return static_cast<double>(std::sqrt(diff / norm) / 0x1p-53L);
}

}  // namespace

Action add_demo(CLI::App& app) {
  auto* cmd = app.add_subcommand("demo", "The main job on built-in defaults: evaluate built-in hinges, summarize");
  auto count = std::make_shared<int>(1000);
  cmd->add_option("--count", *count, "Number of random well-shaped hinges")->capture_default_str()->check(CLI::NonNegativeNumber);
  return [count]() -> int {
    const auto hinges = builtin_hinges(*count, 2013);
    const ScalarType dbl{ScalarType::Kind::kind_double, 0}, oracle{ScalarType::Kind::kind_mpfr, 256};
    using clock = std::chrono::steady_clock;
    std::vector<reference::RoundedTheta> fast_results, oracle_results;
    auto t0 = clock::now();
    for (const auto& h : hinges) fast_results.push_back(evaluate_hinge("reference", dbl, h.x));
    auto t1 = clock::now();
    for (const auto& h : hinges) oracle_results.push_back(evaluate_hinge("reference", oracle, h.x));
    auto t2 = clock::now();
    std::vector<double> errors;
    for (std::size_t i = 0; i < hinges.size(); ++i) errors.push_back(normwise_error(fast_results[i].hess, oracle_results[i].hess));
    std::vector<double> sorted = errors;
    std::sort(sorted.begin(), sorted.end());
    const auto worst = std::max_element(errors.begin(), errors.end()) - errors.begin();
    const double per = 1e6 / static_cast<double>(hinges.size());
    std::cout << "hinge demo: " << hinges.size() << " built-in hinges (3 worked examples of CONVENTIONS.md, " << *count
              << " random well-shaped ones, scales 1e-3..1e3, offsets up to 100)\n";
    for (int i = 0; i < 3; ++i)
      std::cout << "  " << hinges[i].id << ": theta = " << format_double(fast_results[i].theta) << "\n";
    std::cout << "  reference in double vs oracle (mpfr:256), normwise Hessian error in units of 2^-53: median "
              << sorted[sorted.size() / 2] << ", worst " << sorted.back() << " (" << hinges[worst].id << ")\n"
              << "  time per hinge: reference double " << std::chrono::duration<double>(t1 - t0).count() * per
              << " us, oracle " << std::chrono::duration<double>(t2 - t1).count() * per << " us\n";
    return exit_done;
  };
}

}  // namespace hinge::tools
