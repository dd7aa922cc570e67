// Google Benchmark programs for hinge::fast against hinge::reference (bench/README.md):
//   hinge/{fast,reference}                 one hinge: theta, grad theta, Hess theta (double)
//   hinge/fast_many                        the same 1024 hinges in one call (a span)
//   hinge/faithful                         one hinge in the faithful mode (hinge/fast/faithful.hpp)
//   hinge/isa:I                            one hinge, the kernel compiled for I = avx512, avx2, baseline
//                                          (those the processor has; HINGE_ISA, fast/isa.hpp)
//   capi/fast, capi/floor                  1e5 hinges through the C interface of hinge/candidate.h (the
//                                          plugin hinge_candidate_fast.so, loaded with dlopen), one call
//                                          per hinge into distinct slots of arrays far larger than the
//                                          last-level cache; and the memory floor: the same reads (12
//                                          doubles) and writes (157) with no computation
//   capi/many                              the same 1e5 hinges in one library call (a span) into
//                                          HingeDerivatives beyond the cache
//   mesh/{fast,reference}/n:N/threads:T    a whole n x n cloth: energy, gradient and Hessian (tan energy),
//                                          rest state precomputed, the pattern built once (fast)
//   pattern/n:N                            building the fast pattern (once per topology)
// After the runs a summary prints ns (and cycles, from the clock read before and after) per hinge and per
// interior edge, the ratio fast / reference, the two-thread speedup and the exponent k of t = a n^k fitted
// by least squares in log-log (the paper's section 7.3), n the number of vertices.
//
// Environment: HINGE_BENCH_MAX (largest grid side, default 1001: 10^6 vertices), HINGE_BENCH_REFERENCE_MAX
// (largest side for the reference, default 201: it builds 78 triplets per hinge).
#include <benchmark/benchmark.h>
#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hinge/candidate.h"
#include "hinge/core/samples.hpp"
#include "hinge/fast/assemble.hpp"
#include "hinge/fast/faithful.hpp"
#include "hinge/fast/hinge_kernel.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge/reference/assemble.hpp"
#include "hinge/reference/evaluate.hpp"
#include "hinge/study/measure.hpp"

namespace hinge::bench {
namespace {

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v ? std::atoi(v) : fallback;
}

// ---- one hinge ---------------------------------------------------------------------------------------

const std::vector<std::array<double, 12>>& bench_hinges() {
  static const auto h = reference::well_shaped_hinges(1024, 7);
  return h;
}

// `evaluate(x)` on every benchmark hinge, one call each, per iteration.
template <class Evaluate>
void per_hinge(benchmark::State& state, Evaluate&& evaluate) {
  const auto& hs = bench_hinges();
  for (auto _ : state)
    for (const auto& x : hs) {
      auto d = evaluate(x);
      benchmark::DoNotOptimize(d);
    }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(hs.size()));
}

void hinge_fast(benchmark::State& state) {
  per_hinge(state, [](const auto& x) { return fast::hinge_derivatives<double>(x); });
}

void hinge_faithful(benchmark::State& state) {
  per_hinge(state, [](const auto& x) { return fast::faithful_hinge_derivatives(x); });
}

// One hinge a call, the kernel compiled for `isa`.
void hinge_isa(benchmark::State& state, fast::Isa isa) {
  const auto& hs = bench_hinges();
  fast::HingeDerivatives<double> d;
  for (auto _ : state)
    for (const auto& x : hs) {
      fast::hinge_derivatives(isa, x, true, d);
      benchmark::DoNotOptimize(d);
    }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(hs.size()));
}

// ---- the C interface ---------------------------------------------------------------------------------

constexpr std::size_t kCapiHinges = 100000;  // 157 outputs each: 126 MB written, beyond any last-level cache

struct CapiArrays {
  std::vector<std::array<double, 12>> x;
  std::vector<double> theta, grad, hess;
  CapiArrays() : theta(kCapiHinges), grad(12 * kCapiHinges), hess(144 * kCapiHinges) {
    const auto& h = bench_hinges();
    for (std::size_t i = 0; i < kCapiHinges; ++i) x.push_back(h[i % h.size()]);
  }
};
CapiArrays& capi_arrays() {
  static CapiArrays a;
  return a;
}

hinge_candidate_fn* capi_fast() {
  static hinge_candidate_fn* f = [] {
    void* library = dlopen(HINGE_CANDIDATE_FAST, RTLD_NOW | RTLD_LOCAL);
    return library ? reinterpret_cast<hinge_candidate_fn*>(dlsym(library, "hinge_candidate")) : nullptr;
  }();
  return f;
}

void capi_fast_run(benchmark::State& state) {
  hinge_candidate_fn* f = capi_fast();
  if (!f) {
    state.SkipWithError("cannot load " HINGE_CANDIDATE_FAST);
    return;
  }
  CapiArrays& a = capi_arrays();
  for (auto _ : state) {
    for (std::size_t i = 0; i < kCapiHinges; ++i) f(a.x[i].data(), &a.theta[i], &a.grad[12 * i], &a.hess[144 * i]);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kCapiHinges));
}

// The floor: each hinge's 12 doubles read and 157 written to the same slots, the values a cheap function
// of the inputs (so that neither the reads nor the writes can be dropped).
void capi_floor(benchmark::State& state) {
  CapiArrays& a = capi_arrays();
  for (auto _ : state) {
    for (std::size_t i = 0; i < kCapiHinges; ++i) {
      const double* x = a.x[i].data();
      double s = 0;
      for (int k = 0; k < 12; ++k) s += x[k];
      a.theta[i] = s;
      for (int k = 0; k < 12; ++k) a.grad[12 * i + k] = s + k;
      for (int k = 0; k < 144; ++k) a.hess[144 * i + k] = s * k;
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kCapiHinges));
}

// The same 1e5 hinges in one library call (hinge_derivatives over a span) into HingeDerivatives beyond the
// cache (126 MB): the many-hinges path against the same floor.
void capi_many(benchmark::State& state) {
  CapiArrays& a = capi_arrays();
  static std::vector<fast::HingeDerivatives<double>> out(kCapiHinges);
  for (auto _ : state) {
    fast::hinge_derivatives<double>(a.x, out);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kCapiHinges));
}

// The same hinges in one call (hinge_derivatives over a span: with AVX-512 two at a time).
void hinge_fast_many(benchmark::State& state) {
  const auto& hs = bench_hinges();
  std::vector<fast::HingeDerivatives<double>> out(hs.size());
  for (auto _ : state) {
    fast::hinge_derivatives<double>(hs, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(hs.size()));
}

// The certified oracle, one hinge a call: with its fast path (the default), and with the exact stage and
// enclosures alone (what every hinge cost before the fast path).
void hinge_oracle(benchmark::State& state, bool fast_path) {
  oracle::Options options;
  options.fast_path = fast_path;
  per_hinge(state, [&](const auto& x) { return oracle::certified_theta_derivatives(x, options); });
}

void hinge_reference(benchmark::State& state) {
  per_hinge(state, [](const auto& x) { return reference::theta_derivatives<double>(x); });
}

// ---- a whole cloth -----------------------------------------------------------------------------------

// Every grid is kept once built (the repetitions of the sizes are interleaved: main), about 1.5 GB with
// the Hessians up to 1001^2.
struct Cloth {
  int n = 0;
  Mesh rest, deformed;
  Topology topology;
  std::unique_ptr<fast::Assembler<double>> assembler;
  std::vector<HingeCoefficients<double>> coefficients;
  MeshDerivatives<double> out;
};
Cloth& cloth_of(int n) {
  static std::map<int, std::unique_ptr<Cloth>> clothes;
  std::unique_ptr<Cloth>& slot = clothes[n];
  if (!slot) {
    slot = std::make_unique<Cloth>();
    Cloth& c = *slot;
    c.n = n;
    c.rest = cloth(n, 1);
    c.deformed = cloth(n, 2);
    c.topology = build_topology(c.rest);
    c.assembler = std::make_unique<fast::Assembler<double>>(c.topology);
    c.coefficients = c.assembler->rest_state(c.rest, {Model::tan, 1.0, 0}, 2);
  }
  return *slot;
}

void mesh_fast(benchmark::State& state) {
  Cloth& c = cloth_of(static_cast<int>(state.range(0)));
  const int threads = static_cast<int>(state.range(1));
  for (auto _ : state) {
    c.assembler->evaluate(c.deformed, c.coefficients, Model::tan, want_all, threads, c.out);
    benchmark::DoNotOptimize(c.out.energy);
  }
  state.counters["edges"] = static_cast<double>(c.topology.hinges.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.topology.hinges.size()));
}

void mesh_reference(benchmark::State& state) {
  Cloth& c = cloth_of(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    auto m = reference::assemble<double>(c.deformed, c.topology, c.coefficients, Model::tan);
    benchmark::DoNotOptimize(m.energy);
  }
  state.counters["edges"] = static_cast<double>(c.topology.hinges.size());
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(c.topology.hinges.size()));
}

void pattern_build(benchmark::State& state) {
  Cloth& c = cloth_of(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    fast::Pattern p(c.topology);
    benchmark::DoNotOptimize(p.nonzeros());
  }
  state.counters["edges"] = static_cast<double>(c.topology.hinges.size());
}

// ---- summary -------------------------------------------------------------------------------------------

// Keeps each run's real time per iteration (seconds) over the repetitions and reports their median
// (this machine is shared and noisy: the median, not the best or the mean), with the item count.
class Capture : public benchmark::ConsoleReporter {
 public:
  struct Result {
    double seconds = 0;  // median over repetitions
    double items = 0;    // per iteration
    double spread = 0;   // (slowest - fastest) / median over the repetitions
  };
  std::map<std::string, std::vector<double>> times;
  std::map<std::string, double> items;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.run_type != Run::RT_Iteration || r.error_occurred) continue;
      times[r.benchmark_name()].push_back(r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit));
      const auto it = r.counters.find("edges");
      items[r.benchmark_name()] = it != r.counters.end() ? double(it->second) : 1024;
    }
    ConsoleReporter::ReportRuns(runs);
  }
  std::optional<Result> get(const std::string& name) const {
    const auto it = times.find(name);
    if (it == times.end()) return std::nullopt;
    std::vector<double> t = it->second;
    std::sort(t.begin(), t.end());
    const std::size_t m = t.size() / 2;
    const double median = t.size() % 2 ? t[m] : (t[m - 1] + t[m]) / 2;
    return Result{median, items.at(name), (t.back() - t.front()) / median};
  }
};

// Least-squares slope of log t against log n.
double fitted_exponent(const std::vector<std::pair<double, double>>& points) {
  return hinge::study::fit_power_law(points).k;
}

std::string mesh_name(const char* method, int n, int threads) {
  return std::string("mesh/") + method + "/n:" + std::to_string(n) + "/threads:" + std::to_string(threads) +
         "/real_time";
}

void summary(const Capture& c, const std::vector<int>& sides, double ghz_before, double ghz_after) {
  std::printf("\n== summary (double; real time per iteration, median over repetitions) ==\n");
  const double ghz = (ghz_before + ghz_after) / 2;  // cycles below at the mean of the two readings
  if (ghz > 0)
    std::printf("clock: %.2f GHz before the runs, %.2f GHz after (dependent additions)\n", ghz_before, ghz_after);
  const auto hf = c.get("hinge/fast"), hm = c.get("hinge/fast_many"), hr = c.get("hinge/reference");
  if (hf && hr) {
    std::printf("per hinge: fast %.1f ns, reference %.1f ns, fast/reference %.3f", 1e9 * hf->seconds / 1024,
                1e9 * hr->seconds / 1024, hf->seconds / hr->seconds);
    if (ghz > 0) std::printf(" (fast %.0f cycles)", ghz * 1e9 * hf->seconds / 1024);
    std::printf("\n");
  }
  if (hm && hr) {
    std::printf("per hinge, 1024 in one call: fast %.1f ns, fast/reference %.3f", 1e9 * hm->seconds / 1024,
                hm->seconds / hr->seconds);
    if (ghz > 0) std::printf(" (%.0f cycles)", ghz * 1e9 * hm->seconds / 1024);
    std::printf("\n");
  }
  if (const auto hq = c.get("hinge/faithful"); hq && hf) {
    std::printf("per hinge, faithful mode: %.1f ns, faithful/fast %.2f", 1e9 * hq->seconds / 1024,
                hq->seconds / hf->seconds);
    if (ghz > 0) std::printf(" (%.0f cycles)", ghz * 1e9 * hq->seconds / 1024);
    std::printf("\n");
  }
  if (const auto ho = c.get("hinge/oracle"); ho && hf) {
    std::printf("per hinge, certified oracle: %.2f us with the fast path, %.1f x hinge/fast", 1e6 * ho->seconds / 1024,
                ho->seconds / hf->seconds);
    if (const auto he = c.get("hinge/oracle_enclosures"))
      std::printf("; %.1f us by the exact stage and enclosures alone (%.1f x the fast path)", 1e6 * he->seconds / 1024,
                  he->seconds / ho->seconds);
    std::printf("\n");
  }
  if (const auto cf = c.get("capi/fast"), floor = c.get("capi/floor"); cf && floor) {
    std::printf(
        "C interface, 1e5 hinges one call each: fast %.1f ns per hinge, memory floor %.1f ns, fast/floor %.2f\n",
        1e9 * cf->seconds / kCapiHinges, 1e9 * floor->seconds / kCapiHinges, cf->seconds / floor->seconds);
    if (const auto many = c.get("capi/many"))
      std::printf(
          "the same 1e5 hinges in one library call (hinge_derivatives over a span): %.1f ns per hinge, /floor %.2f\n",
          1e9 * many->seconds / kCapiHinges, many->seconds / floor->seconds);
  }
  if (const auto best = c.get("hinge/isa:avx512")) {
    std::printf("per hinge by instruction set (one call per hinge): avx512 %.1f ns", 1e9 * best->seconds / 1024);
    for (const char* isa : {"avx2", "baseline"})
      if (const auto r = c.get(std::string("hinge/isa:") + isa))
        std::printf(", %s %.1f ns (%.2f x avx512)", isa, 1e9 * r->seconds / 1024, r->seconds / best->seconds);
    std::printf("\n");
  }
  std::printf("%7s %10s %10s %14s %10s %8s %14s %9s %14s %14s\n", "side", "vertices", "edges", "fast 1T ns/e",
              "cycles/e", "spread", "fast 2T ns/e", "speedup", "ref ns/edge", "fast/ref");
  std::vector<std::pair<double, double>> fit_all, fit_large, fit_paper, fit_ref;
  for (int n : sides) {
    const auto f1 = c.get(mesh_name("fast", n, 1)), f2 = c.get(mesh_name("fast", n, 2)),
               r = c.get(mesh_name("reference", n, 1));
    if (!f1) continue;
    const double vertices = double(n) * n, edges = f1->items;
    std::printf("%7d %10.0f %10.0f %14.1f", n, vertices, edges, 1e9 * f1->seconds / edges);
    if (ghz > 0) std::printf(" %10.0f", ghz * 1e9 * f1->seconds / edges);
    else std::printf(" %10s", "-");
    std::printf(" %7.0f%%", 100 * f1->spread);
    if (f2) std::printf(" %14.1f %9.2f", 1e9 * f2->seconds / edges, f1->seconds / f2->seconds);
    else std::printf(" %14s %9s", "-", "-");
    if (r) std::printf(" %14.1f %14.3f\n", 1e9 * r->seconds / edges, f1->seconds / r->seconds);
    else std::printf(" %14s %14s\n", "-", "-");
    fit_all.emplace_back(vertices, f1->seconds);
    if (n >= 101) fit_large.emplace_back(vertices, f1->seconds);
    if (n <= 81) fit_paper.emplace_back(vertices, f1->seconds);
    if (r) fit_ref.emplace_back(vertices, r->seconds);
  }
  if (fit_large.size() >= 2)
    std::printf("fast, 1 thread: t = a n^k with k = %.3f (101^2 .. %d^2 vertices)\n", fitted_exponent(fit_large),
                sides.back());
  if (fit_paper.size() >= 2)
    std::printf("fast, 1 thread: k = %.3f over the paper's sizes (11^2 .. 81^2)\n", fitted_exponent(fit_paper));
  if (fit_all.size() >= 2) std::printf("fast, 1 thread: k = %.3f over all sizes\n", fitted_exponent(fit_all));
  if (fit_ref.size() >= 2) std::printf("reference: k = %.3f over its sizes\n", fitted_exponent(fit_ref));
}

}  // namespace
}  // namespace hinge::bench

int main(int argc, char** argv) {
  using namespace hinge::bench;
  const int largest = env_int("HINGE_BENCH_MAX", 1001), reference_largest = env_int("HINGE_BENCH_REFERENCE_MAX", 201);
  std::vector<int> sides;
  for (int n : {11, 21, 41, 81, 101, 201, 401, 1001})
    if (n <= largest) sides.push_back(n);
  if (largest > 1001) sides.push_back(largest);

  benchmark::RegisterBenchmark("hinge/fast", hinge_fast);
  benchmark::RegisterBenchmark("hinge/fast_many", hinge_fast_many);
  benchmark::RegisterBenchmark("hinge/reference", hinge_reference);
  benchmark::RegisterBenchmark("hinge/faithful", hinge_faithful);
  benchmark::RegisterBenchmark("hinge/oracle", hinge_oracle, true)->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("hinge/oracle_enclosures", hinge_oracle, false)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("capi/fast", capi_fast_run)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("capi/floor", capi_floor)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("capi/many", capi_many)->Unit(benchmark::kMillisecond);
  for (hinge::fast::Isa isa : {hinge::fast::Isa::avx512, hinge::fast::Isa::avx2, hinge::fast::Isa::baseline})
    if (hinge::fast::isa_available(isa))
      benchmark::RegisterBenchmark(("hinge/isa:" + std::string(hinge::fast::isa_name(isa))).c_str(), hinge_isa, isa);
  for (int n : sides) {
    benchmark::RegisterBenchmark("pattern", pattern_build)->ArgNames({"n"})->Args({n})->Unit(benchmark::kMillisecond);
    for (int threads : {1, 2})
      benchmark::RegisterBenchmark("mesh/fast", mesh_fast)
          ->ArgNames({"n", "threads"})
          ->Args({n, threads})
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
    if (n <= reference_largest)
      benchmark::RegisterBenchmark("mesh/reference", mesh_reference)
          ->ArgNames({"n", "threads"})
          ->Args({n, 1})
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
  }
  // Defaults, unless given: 5 repetitions, interleaved in random order, so that the clock's drift (this
  // machine's moves by ~10% within an hour) falls on every size alike and not on the fitted k.
  std::vector<char*> args(argv, argv + argc);
  auto given = [&](const char* flag) {
    return std::any_of(args.begin(), args.end(),
                       [flag](const char* a) { return std::strncmp(a, flag, std::strlen(flag)) == 0; });
  };
  static char repetitions[] = "--benchmark_repetitions=5", interleave[] = "--benchmark_enable_random_interleaving=true";
  if (!given("--benchmark_repetitions")) args.push_back(repetitions);
  if (!given("--benchmark_enable_random_interleaving")) args.push_back(interleave);
  argc = static_cast<int>(args.size());
  args.push_back(nullptr);
  argv = args.data();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const double ghz_before = hinge::study::clock_ghz();
  Capture capture;
  benchmark::RunSpecifiedBenchmarks(&capture);
  summary(capture, sides, ghz_before, hinge::study::clock_ghz());
  benchmark::Shutdown();
  return 0;
}
