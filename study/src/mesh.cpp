// The study's mesh level: whole evaluations (energy, gradient, Hessian of the tan energy) on the
// benchmark's cloth, per interior edge, and the fitted t = a n^k (the paper's section 7.3, Table 2).
#include <algorithm>
#include <chrono>
#include <cmath>

#include "hinge/core/samples.hpp"
#include "hinge/study/measure.hpp"
#include "study_internal.hpp"

namespace hinge::study::detail {

MeshRow measure_mesh(methods::Method method, const ScalarType& scalar, const std::vector<int>& sizes, double budget,
                     bool quick) {
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); };
  const auto start = Clock::now();
  MeshRow row;
  row.method = method;
  row.scalar = scalar;
  const int min_runs = quick ? 3 : 5;
  const double min_seconds = quick ? 0.05 : 0.5;
  double last = 0;  // seconds per evaluation at the previous size
  int last_n = 0;
  for (const int n : sizes) {
    // The next size costs about (n / last_n)^2 times the last one's evaluation, min_runs + 1 times.
    if (last_n && since(start) + (min_runs + 1) * last * std::pow(double(n) / last_n, 2) > budget) break;
    const Mesh rest = cloth(n, 1), deformed = cloth(n, 2);  // the benchmark's cloth (hinge/core/samples.hpp)
    const Topology topology = build_topology(rest);
    const methods::MeshInput input{&deformed, &rest, &topology, {Model::tan, 1.0, 0}, want_all, 1};
    methods::MeshEvaluator evaluator(method, scalar, input);
    evaluator.evaluate();  // warm-up: first-touch of the work arrays and the matrix
    std::vector<double> runs;
    double spent = 0;
    while (static_cast<int>(runs.size()) < min_runs || spent < min_seconds) {
      const auto t0 = Clock::now();
      evaluator.evaluate();
      runs.push_back(since(t0));
      spent += runs.back();
      if (since(start) > budget && runs.size() >= 1) break;
    }
    std::sort(runs.begin(), runs.end());
    last = runs[runs.size() / 2];
    last_n = n;
    row.vertices.push_back(double(n) * n);
    row.interior_edges.push_back(double(topology.hinges.size()));
    row.seconds.push_back(last);
    row.ns_per_edge.push_back(1e9 * last / double(topology.hinges.size()));
  }
  if (row.vertices.size() >= 2) {
    std::vector<std::pair<double, double>> points;
    for (std::size_t i = 0; i < row.vertices.size(); ++i) points.emplace_back(row.vertices[i], row.seconds[i]);
    const PowerLaw fit = fit_power_law(points);
    row.k = fit.k;
    row.ln_a = fit.ln_a;
  }
  return row;
}

SharedFit shared_fit(const std::vector<MeshRow>& mesh, ScalarType::Kind kind) {
  SharedFit f;
  std::vector<std::pair<std::string, std::vector<std::pair<double, double>>>> series;
  for (const MeshRow& m : mesh) {
    if (m.scalar.kind != kind) continue;
    std::vector<std::pair<double, double>> points;
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
      if (m.vertices[i] <= 81 * 81) points.emplace_back(m.vertices[i], m.seconds[i]);
    if (points.size() >= 2) series.emplace_back(std::string(methods::method_name(m.method)), points);
  }
  if (series.size() < 2) return f;
  for (const auto& [method, points] : series) f.k += fit_power_law(points).k / double(series.size());
  for (const auto& [method, points] : series) {
    f.ln_a.emplace_back(method, fit_ln_a(points, f.k));
    if (method == "fast") f.fast_ln_a = f.ln_a.back().second, f.has_fast = true;
  }
  return f;
}

}  // namespace hinge::study::detail
