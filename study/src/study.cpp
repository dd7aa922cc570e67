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

Row run_row(methods::Method method, const ScalarType& scalar, const Prepared& p, double budget, bool quick) {
  return visit_scalar_type(scalar,
                           [&]<class Scalar>() { return measure_row<Scalar>(method, scalar, p, budget, quick); });
}

// A row is on the frontier when no other row is at least as fast (all three outputs) and at least as
// accurate (its worst error of any output group in any category), and better in one of the two.
void mark_frontier(std::vector<Row>& rows) {
  for (Row& r : rows) {
    r.worst = r.worst_hess = 0;
    for (const auto& [category, e] : r.error_u) {
      r.worst_hess = std::max(r.worst_hess, e[2].max);
      for (const ErrorStats& g : e) r.worst = std::max(r.worst, g.max);
    }
  }
  const auto usable = [](const Row& r) {
    return r.ns_per_hinge[2] > 0 && !r.error_u.empty() && r.failed + r.nonfinite == 0;
  };
  for (Row& r : rows) {
    r.on_frontier = usable(r);
    for (const Row& o : rows)
      if (&o != &r && usable(o) && o.ns_per_hinge[2] <= r.ns_per_hinge[2] && o.worst <= r.worst &&
          (o.ns_per_hinge[2] < r.ns_per_hinge[2] || o.worst < r.worst))
        r.on_frontier = false;
  }
}

}  // namespace
}  // namespace detail

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
  const std::vector<methods::Method> methods_ =
      o.methods.empty() ? std::vector<methods::Method>{methods::Method::reference, methods::Method::fast,
                                                       methods::Method::autodiff, methods::Method::symbolic}
                        : o.methods;
  const std::vector<ScalarType> scalars = o.scalars.empty() ? default_scalars(o.quick) : o.scalars;
  if (methods_.empty() || scalars.empty())
    throw std::invalid_argument("hinge study: no method or no scalar type to study");
  const double budget = o.budget_seconds > 0 ? o.budget_seconds : (o.quick ? 1.5 : 20);

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

  std::size_t done = 0;
  const std::size_t total = methods_.size() * scalars.size();
  for (const ScalarType& scalar : scalars)
    for (const methods::Method m : methods_) {
      if (o.progress) o.progress("rows: " + std::string(methods::method_name(m)) + " in " + scalar.name(), done, total);
      s.rows.push_back(detail::run_row(m, scalar, p, budget, o.quick));
      ++done;
    }
  if (o.progress) o.progress("rows", total, total);
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
