// hinge study: the rows, the mesh level, the frontier (hinge/study/study.hpp).
#include <algorithm>
#include <chrono>
#include <fstream>
#include <stdexcept>
#include <string_view>

#include "hinge/core/build_info.hpp"
#include "hinge/reference/evaluate.hpp"
#include "hinge/study/measure.hpp"
#include "rows.hpp"
#include "study_internal.hpp"

namespace hinge::study {

namespace detail {

GroupErrors statistics(std::array<std::vector<double>, 3>& errors) {
  GroupErrors s;
  for (int g = 0; g < 3; ++g) {
    auto& v = errors[g];
    if (v.empty()) continue;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    s[g].median = n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
    s[g].max = v.back();
  }
  return s;
}

void record_errors(Row& row, const Prepared& p, std::size_t i, const RoundedTheta& rounded,
                   std::array<std::vector<double>, 3>& e) {
  const oracle::CertifiedTheta& c = p.certified[i];
  namespace conf = conformance;
  e[0].push_back(conf::normwise_error(&rounded.theta, &c.theta, 1, p.scale[i][0]));
  e[1].push_back(conf::normwise_error(rounded.grad.data(), c.grad.data(), 12, p.scale[i][1]));
  e[2].push_back(conf::normwise_error(rounded.hess.data(), c.hess.data(), 144, p.scale[i][2]));
  row.hess_errors.push_back(e[2].back());
}

std::string cpu_name() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown";
}

namespace {

Measured run_row(methods::Method method, const ScalarType& scalar, const Prepared& p, double budget, bool quick) {
  return visit_scalar_type(scalar,
                           [&]<class Scalar>() { return measure_row<Scalar>(method, scalar, p, budget, quick); });
}

// A row is on the frontier when no other row is at least as fast (all three outputs, as ratios to fast in
// double measured side by side) and at least as accurate (its worst error of any output group in any
// category), and better in one of the two: at equal error the faster row is on it.
void mark_frontier(std::vector<Row>& rows) {
  for (Row& r : rows) {
    r.worst = r.worst_hess = 0;
    for (const auto& [category, e] : r.error_u) {
      r.worst_hess = std::max(r.worst_hess, e[2].max);
      for (const ErrorStats& g : e) r.worst = std::max(r.worst, g.max);
    }
  }
  const auto usable = [](const Row& r) { return r.x_fast[2] > 0 && !r.error_u.empty() && r.failed + r.nonfinite == 0; };
  for (Row& r : rows) {
    r.on_frontier = usable(r);
    for (const Row& o : rows)
      if (&o != &r && usable(o) && o.x_fast[2] <= r.x_fast[2] && o.worst <= r.worst &&
          (o.x_fast[2] < r.x_fast[2] || o.worst < r.worst))
        r.on_frontier = false;
  }
}

}  // namespace
}  // namespace detail

std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const auto& m : methods::method_names()) names.emplace_back(m);
  names.emplace_back("faithful");
  names.emplace_back("oracle");
  return names;
}

std::string check_method(const std::string& name) {
  const auto names = method_names();
  if (std::find(names.begin(), names.end(), name) == names.end()) {
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    std::string message = "unknown method '";
    message += name;
    message += "' (the study's methods: ";
    message += known;
    message += ")";
    throw std::invalid_argument(message);
  }
  return name;
}

std::vector<ScalarType> default_scalars(bool quick) {
  std::vector<ScalarType> s;
  for (const char* name : {"float", "double", "long-double", "dd", "qd", "float128", "bin128", "mpfr:128", "mpfr:256"})
    if (HINGE_HAVE_FLOAT128 || std::string_view(name) != "float128") s.push_back(parse_scalar_type(name));
  if (!quick) s.push_back(parse_scalar_type("mpfr:512"));
  return s;
}

Study run(const Options& o) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  std::vector<std::string> names = o.methods.empty() ? method_names() : o.methods;
  for (const auto& n : names) check_method(n);
  const std::vector<ScalarType> scalars = o.scalars.empty() ? default_scalars(o.quick) : o.scalars;
  if ((names.empty() || scalars.empty()) && o.outside.empty())
    throw std::invalid_argument("hinge study: no method or no scalar type to study");
  const double budget = o.budget_seconds > 0 ? o.budget_seconds : (o.quick ? 1.5 : 20);
  const bool has_double = std::any_of(scalars.begin(), scalars.end(),
                                      [](const ScalarType& t) { return t.kind == ScalarType::Kind::kind_double; });
  std::vector<methods::Method> methods_;  // those of hinge::methods, in every type
  for (const auto& n : names)
    if (n != "faithful" && n != "oracle") methods_.push_back(methods::parse_method(n));
  const auto wanted = [&](const char* n) {
    return has_double && std::find(names.begin(), names.end(), n) != names.end();
  };

  Study s;
  s.quick = o.quick;
  s.source = o.source;
  s.cpu = detail::cpu_name();
  s.clock_ghz = clock_ghz();
  s.build = hinge::build_description();

  const bool builtin = o.hinges.empty();
  std::vector<std::array<double, 12>> timing;
  if (builtin) timing = reference::well_shaped_hinges(256, 2013);  // the common case; the user's own hinges otherwise
  const detail::Prepared p(builtin ? builtin_hinges(o.quick) : o.hinges, std::move(timing), o.progress);
  s.hinges = p.hinges.size();
  s.skipped = p.skipped;
  s.categories = p.categories;
  s.timing = detail::timing_description(p.timing.size(), builtin, detail::round_policy(o.quick));

  // Errors row by row, then every row's timing rounds in turn (timing.hpp).
  std::size_t done = 0;
  const std::size_t total = methods_.size() * scalars.size() + wanted("faithful") + wanted("oracle") + o.outside.size();
  const auto progress = [&](const std::string& what) {
    if (o.progress) o.progress("rows: " + what, done, total);
  };
  std::vector<std::optional<detail::RowTimer>> timers;
  const auto add = [&](detail::Measured m) {
    s.rows.push_back(std::move(m.row));
    timers.push_back(std::move(m.timer));
    ++done;
  };
  for (const ScalarType& scalar : scalars) {
    for (const methods::Method m : methods_) {
      progress(std::string(methods::method_name(m)) + " in " + scalar.name());
      add(detail::run_row(m, scalar, p, budget, o.quick));
    }
    if (scalar.kind != ScalarType::Kind::kind_double) continue;
    if (wanted("faithful")) {
      progress("faithful in double");
      add(detail::measure_faithful(p, budget, o.quick));
    }
    if (wanted("oracle")) {
      progress("oracle in double");
      add(detail::measure_oracle(p, budget, o.quick));
    }
  }
  for (const Outside& outside : o.outside) {
    progress(outside.label + " (outside)");
    add(detail::measure_outside(outside, p, budget, o.quick));
  }
  if (o.progress) o.progress("rows", total, total);
  const auto timing_start = Clock::now();
  for (int round = 0;; ++round) {
    std::size_t left = 0;
    for (auto& t : timers)
      if (t && !t->done()) {
        t->round(round);
        ++left;
      }
    if (o.progress && round % 25 == 0)
      o.progress("timing: round " + std::to_string(round + 1) + ", rows done", total - left, total);
    if (left == 0) break;
  }
  for (std::size_t i = 0; i < timers.size(); ++i)
    if (timers[i]) timers[i]->finish(s.rows[i]);
  s.timing_seconds = std::chrono::duration<double>(Clock::now() - timing_start).count();
  detail::mark_frontier(s.rows);

  if (o.mesh) {
    // The paper's cloth sizes, 11^2 .. 81^2 (the quick study: 11^2 .. 41^2), every method in double; the
    // full study also every method in the other types, and fast in double on to 1001^2.
    const std::vector<int> paper =
        o.quick ? std::vector<int>{11, 21, 41} : std::vector<int>{11, 21, 31, 41, 51, 61, 71, 81};
    std::vector<std::pair<methods::Method, ScalarType>> mesh_rows;
    const ScalarType dbl = parse_scalar_type("double");
    for (const methods::Method m : methods_)
      for (const ScalarType& scalar : scalars)
        if (scalar.kind == dbl.kind || !o.quick) mesh_rows.emplace_back(m, scalar);
    std::size_t k = 0;
    for (const auto& [m, scalar] : mesh_rows) {
      if (o.progress)
        o.progress("mesh: " + std::string(methods::method_name(m)) + " in " + scalar.name(), k++, mesh_rows.size());
      std::vector<int> sizes = paper;
      if (m == methods::Method::fast && scalar.kind == dbl.kind) {
        sizes.push_back(o.quick ? 81 : 101);
        if (!o.quick) sizes.insert(sizes.end(), {201, 401, 1001});
      }
      s.mesh.push_back(detail::measure_mesh(m, scalar, sizes, budget, o.quick));
    }
    if (o.progress) o.progress("mesh", mesh_rows.size(), mesh_rows.size());
    s.shared_fit = detail::shared_fit(s.mesh, ScalarType::Kind::kind_double);
  }
  s.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return s;
}

}  // namespace hinge::study
