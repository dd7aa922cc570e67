// hinge._hinge's conformance part: the committed conformance sets and the report of a graded run, for
// hinge.conform (python/hinge/conformance.py), which calls the candidate, maps its stencil and hands the
// outputs, in the contract's order, to hinge::conformance::make_report: the grading, tiers and diagnosis
// are those of `hinge conform`, and the text, JSON and HTML reports the same functions write.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <sstream>
#include <stdexcept>

#include "bindings.hpp"
#include "hinge/conformance/consistency.hpp"
#include "hinge/conformance/energy_report.hpp"
#include "hinge/conformance/html_report.hpp"
#include "hinge/conformance/report.hpp"
#include "hinge/conformance/sets.hpp"
#include "hinge/io/atomic_file.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace hinge::python {
namespace {

namespace conf = hinge::conformance;

// (ids, categories, x (n, 12) float64: the contract's order, exactly the set's numbers).
py::tuple conformance_set(const std::string& dtype, const std::string& depth) {
  const auto& set = parsed([&]() -> const auto& {
    return conf::conformance_set(conf::parse_dtype(dtype), conf::parse_depth(depth));
  });
  py::list ids, categories;
  const auto n = static_cast<py::ssize_t>(set.size());
  py::array_t<double> x({n, py::ssize_t{12}});
  double* out = x.mutable_data();
  for (std::size_t i = 0; i < set.size(); ++i) {
    ids.append(set[i].input.id);
    categories.append(set[i].input.category);
    std::copy(set[i].input.x.begin(), set[i].input.x.end(), out + 12 * i);
  }
  return py::make_tuple(ids, categories, x);
}

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

// Grades the candidate's outputs (the contract's order, float64; status per case 0 missing, 1 error, 2
// non-finite, 3 ok as io::EvalOutput::Status; `errors` the reason per case, "" if none).
conf::Report grade(const std::string& candidate, const std::string& dtype, const std::string& depth,
                   const std::array<bool, 3>& given, const conf::Stencil& stencil, const Array& theta,
                   const Array& grad, const Array& hess, const std::vector<int>& status,
                   const std::vector<std::string>& errors, const std::vector<std::string>& notes) {
  conf::Grading grading;
  grading.dtype = parsed([&] { return conf::parse_dtype(dtype); });
  grading.given = given;
  const conf::Depth d = parsed([&] { return conf::parse_depth(depth); });
  std::vector<conf::Expected> expected = conf::conformance_set(grading.dtype, d);
  const std::size_t n = expected.size();
  if (static_cast<std::size_t>(theta.size()) != n || static_cast<std::size_t>(grad.size()) != 12 * n ||
      static_cast<std::size_t>(hess.size()) != 144 * n || status.size() != n || errors.size() != n)
    throw py::value_error("grade: one row per case of the set");
  std::vector<conf::CandidateResult> results(n);
  for (std::size_t i = 0; i < n; ++i) {
    conf::CandidateResult& r = results[i];
    if (status[i] < 0 || status[i] > 3) throw py::value_error("grade: status must be 0..3");
    r.status = static_cast<conf::CandidateResult::Status>(status[i]);
    r.error = errors[i];
    r.theta = theta.data()[i];
    std::copy_n(grad.data() + 12 * i, 12, r.grad.begin());
    std::copy_n(hess.data() + 144 * i, 144, r.hess.begin());
  }
  py::gil_scoped_release release;
  conf::Report report = conf::make_report(candidate, std::move(expected), std::move(results), grading, stencil, depth);
  report.notes = notes;
  return report;
}

// The set an energy name grades on ("custom": the shells set, whose pairs are all finite: only its
// consistency base is used; "quadratic": its own, flat rest hinges).
const conf::EnergySet& set_of(const std::string& energy, const std::string& depth, const std::string& dtype) {
  return parsed([&]() -> const auto& {
    const conf::Depth d = conf::parse_depth(depth);
    const conf::Dtype t = conf::parse_dtype(dtype);
    if (energy == "quadratic") return conf::quadratic_set(d, t);
    return conf::energy_set(parse_model(energy == "custom" ? "shells" : energy), d, t);
  });
}

py::array_t<double> rows(const std::vector<std::array<double, 12>>& v) {
  py::array_t<double> a({static_cast<py::ssize_t>(v.size()), py::ssize_t{12}});
  for (std::size_t i = 0; i < v.size(); ++i) std::copy(v[i].begin(), v[i].end(), a.mutable_data() + 12 * i);
  return a;
}

// (ids, categories, x (n, 12), rest (n, 12), left_out): the energy's graded pairs, the contract's order.
py::tuple energy_set(const std::string& energy, const std::string& depth, const std::string& dtype) {
  const conf::EnergySet& set = set_of(energy, depth, dtype);
  py::list ids, categories;
  std::vector<std::array<double, 12>> x, rest;
  for (const conf::EnergyCase& c : set.cases) {
    ids.append(c.id);
    categories.append(c.category);
    x.push_back(c.x);
    rest.push_back(c.rest);
  }
  return py::make_tuple(ids, categories, rows(x), rows(rest), set.left_out);
}

std::vector<double> energy_weights(const std::string& energy, const std::string& weight, const std::string& depth,
                                   const std::string& dtype) {
  return parsed([&] { return conf::set_weights(set_of(energy, depth, dtype), weight); });
}

// (x (m, 12), rest (m, 12), base): the consistency checks' probes in the contract's order, and the indices of
// their base hinges in the energy's set.
py::tuple consistency_probes(const std::string& energy, const std::string& dtype, const std::string& depth) {
  const conf::EnergySet& set = set_of(energy, depth, dtype);
  const std::vector<std::size_t> base = conf::consistency_base(set);
  std::vector<conf::EnergyCase> cases;
  for (const std::size_t i : base) cases.push_back(set.cases[i]);
  const conf::ConsistencyPlan plan = parsed([&] { return conf::consistency_plan(cases, conf::parse_dtype(dtype)); });
  return py::make_tuple(rows(plan.x), rows(plan.rest), base);
}

// Grades a bending term: its outputs on the energy's set (the contract's order; status as in grade()) and on
// the consistency probes (ok per probe), `weights` its w per case of the set (empty: the named weight).
conf::Report energy_grade(const std::string& candidate, const std::string& energy, double k, const std::string& hessian,
                          const std::string& weight, const std::vector<double>& weights, bool diagonal,
                          const std::string& dtype, const std::array<bool, 3>& given, const conf::Stencil& stencil,
                          const Array& values, const Array& grad, const Array& hess, const std::vector<int>& status,
                          const std::vector<std::string>& errors, const std::vector<std::string>& notes,
                          const Array& probe_values, const Array& probe_grad, const Array& probe_hess,
                          const std::vector<bool>& probe_ok, const std::string& depth) {
  const conf::EnergyGrading eg = parsed([&] { return conf::energy_grading(energy, weight, k, hessian, diagonal); });
  const conf::EnergySet& set = set_of(energy, depth, dtype);
  conf::Grading grading;
  grading.dtype = parsed([&] { return conf::parse_dtype(dtype); });
  grading.given = given;

  const std::size_t m = probe_ok.size();
  if (static_cast<std::size_t>(probe_values.size()) != m || static_cast<std::size_t>(probe_grad.size()) != 12 * m ||
      static_cast<std::size_t>(probe_hess.size()) != 144 * m)
    throw py::value_error("energy_grade: one row per consistency probe");
  std::vector<conf::EnergyOutputs> probes(m);
  for (std::size_t i = 0; i < m; ++i) {
    probes[i].ok = probe_ok[i];
    probes[i].energy = probe_values.data()[i];
    std::copy_n(probe_grad.data() + 12 * i, 12, probes[i].grad.begin());
    std::copy_n(probe_hess.data() + 144 * i, 144, probes[i].hess.begin());
  }
  std::vector<conf::CandidateResult> results;
  if (!eg.custom) {
    const std::size_t n = set.cases.size();
    if (static_cast<std::size_t>(values.size()) != n || static_cast<std::size_t>(grad.size()) != 12 * n ||
        static_cast<std::size_t>(hess.size()) != 144 * n || status.size() != n || errors.size() != n)
      throw py::value_error("energy_grade: one row per case of the set");
    results.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      conf::CandidateResult& r = results[i];
      if (status[i] < 0 || status[i] > 3) throw py::value_error("energy_grade: status must be 0..3");
      r.status = static_cast<conf::CandidateResult::Status>(status[i]);
      r.error = errors[i];
      r.theta = values.data()[i];
      std::copy_n(grad.data() + 12 * i, 12, r.grad.begin());
      std::copy_n(hess.data() + 144 * i, 144, r.hess.begin());
    }
  }
  py::gil_scoped_release release;
  conf::Report report = parsed(
      [&] { return conf::grade_energy(candidate, set, eg, grading, weights, std::move(results), probes, stencil); });
  report.notes.insert(report.notes.begin(), notes.begin(), notes.end());
  return report;
}

}  // namespace

void bind_conformance(py::module_& m) {
  py::class_<conf::Report>(m, "ConformanceReport", "A graded conformance run (hinge.conform builds it)")
      .def_readonly("passed", &conf::Report::passed)
      .def_property_readonly("tier", [](const conf::Report& r) { return std::string(conf::tier_name(r.tier)); })
      .def_property_readonly("diagnosis",
                             [](const conf::Report& r) {
                               std::vector<std::string> out;
                               for (const auto& f : r.diagnosis) out.push_back(f.sentence);
                               return out;
                             })
      .def("text",
           [](const conf::Report& r) {
             std::ostringstream out;
             conf::print_report(out, r);
             return out.str();
           })
      .def("json",
           [](const conf::Report& r) {
             std::ostringstream out;
             conf::write_json_report(out, r);
             return out.str();
           })
      .def(
          "write_html",
          [](const conf::Report& r, const std::string& path) {
            try {
              hinge::io::AtomicFile f(path);
              conf::write_html_report(f.stream(), r);
              f.commit();
            } catch (const std::runtime_error& e) {
              PyErr_SetString(PyExc_OSError, e.what());
              throw py::error_already_set();
            }
          },
          "path"_a);
  m.def("conformance_set", &conformance_set, "dtype"_a, "depth"_a);
  m.def("energy_set", &energy_set, "energy"_a, "depth"_a = "quick", "dtype"_a = "float64");
  m.def("energy_weights", &energy_weights, "energy"_a, "weight"_a, "depth"_a = "quick", "dtype"_a = "float64");
  m.def("energy_weight_names", &conf::weight_names);
  m.def("consistency_probes", &consistency_probes, "energy"_a, "dtype"_a, "depth"_a = "quick");
  m.def("energy_grade", &energy_grade, "candidate"_a, "energy"_a, "k"_a, "hessian"_a, "weight"_a, "weights"_a,
        "diagonal"_a, "dtype"_a, "given"_a, "stencil"_a, "values"_a, "grad"_a, "hess"_a, "status"_a, "errors"_a,
        "notes"_a, "probe_values"_a, "probe_grad"_a, "probe_hess"_a, "probe_ok"_a, "depth"_a = "quick");
  m.def("conformance_grade", &grade, "candidate"_a, "dtype"_a, "depth"_a, "given"_a, "stencil"_a, "theta"_a, "grad"_a,
        "hess"_a, "status"_a, "errors"_a, "notes"_a = std::vector<std::string>{});
}

}  // namespace hinge::python
