// hinge demo: the main job on built-in defaults. Evaluates built-in hinges (the worked examples of
// docs/examples and random well-shaped ones, rotated, scaled and offset) with the fast kernel and the
// reference in double, against the certified oracle, and prints a short summary: normwise Hessian error in
// units of 2^-53 and time per hinge.
#include <algorithm>
#include <chrono>
#include <iostream>

#include "commands.hpp"
#include "hinge/io/number.hpp"
#include "hinge/methods/methods.hpp"
#include "hinge/oracle/conformance.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge/reference/samples.hpp"

namespace hinge::tools {

namespace {

struct NamedHinge {
  std::string id;
  std::array<double, 12> x;
};

std::vector<NamedHinge> builtin_hinges(int random_count, unsigned seed) {
  std::vector<NamedHinge> hinges = {  // docs/examples/eval-input.jsonl
      {"flat", {0.5, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.5, -1.0, 0.0}},
      {"valley", {0.5, 1.0, 0.25, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.25, -1.0, 0.5}},
      {"generic", {0.125, 0.75, -0.5, -0.25, 0.0625, 0.0, 1.0, 0.125, -0.0625, 0.625, -0.875, 0.375}}};
  int i = 0;
  for (const auto& x : well_shaped_hinges(random_count, seed)) hinges.push_back({"random-" + std::to_string(i++), x});
  return hinges;
}

}  // namespace

Action add_demo(CLI::App& app) {
  auto* cmd = app.add_subcommand("demo", "The main job on built-in defaults: evaluate built-in hinges, summarize");
  auto count = std::make_shared<int>(1000);
  cmd->add_option("--count", *count, "Number of random well-shaped hinges")->capture_default_str()->check(CLI::NonNegativeNumber);
  return [count]() -> int {
    const auto hinges = builtin_hinges(*count, 2013);
    using clock = std::chrono::steady_clock;
    std::vector<oracle::CertifiedTheta> certified;
    const auto t0 = clock::now();
    for (const auto& h : hinges) certified.push_back(oracle::certified_theta_derivatives(h.x));
    const double oracle_us = std::chrono::duration<double, std::micro>(clock::now() - t0).count();
    const double per = 1.0 / static_cast<double>(hinges.size());
    std::cout << "hinge demo: " << hinges.size() << " built-in hinges (3 worked examples of docs/examples, " << *count
              << " random well-shaped ones, scales 1e-3..1e3, offsets up to 100)\n";
    for (int i = 0; i < 3; ++i) std::cout << "  " << hinges[i].id << ": theta = " << io::format_double(certified[i].theta) << "\n";
    const ScalarType dbl{ScalarType::Kind::kind_double, 0};
    for (const methods::Method m : {methods::Method::fast, methods::Method::reference}) {
      std::vector<reference::RoundedTheta> results;
      const auto t1 = clock::now();
      for (const auto& h : hinges) results.push_back(methods::evaluate_hinge(m, dbl, h.x));
      const double us = std::chrono::duration<double, std::micro>(clock::now() - t1).count();
      std::vector<double> errors;
      for (std::size_t i = 0; i < hinges.size(); ++i)
        errors.push_back(oracle::conformance::normwise_error(results[i].hess.data(), certified[i].hess.data(), 144, 1));
      const auto worst = std::max_element(errors.begin(), errors.end()) - errors.begin();
      std::vector<double> sorted = errors;
      std::sort(sorted.begin(), sorted.end());
      std::cout << "  " << methods::method_name(m) << " in double vs the certified oracle, normwise Hessian error in units of "
                << "2^-53: median " << sorted[sorted.size() / 2] << ", worst " << sorted.back() << " (" << hinges[worst].id
                << "); " << us * per << " us per hinge\n";
    }
    std::cout << "  certified oracle: " << oracle_us * per << " us per hinge\n";
    return exit_done;
  };
}

}  // namespace hinge::tools
