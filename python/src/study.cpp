// hinge._hinge's study part: hinge::study::run with Python callables as outside rows, for hinge.study
// (python/hinge/study.py), which wraps each callable of hinge.conform into `evaluate` (the contract's order,
// the candidate's stencil mapped as hinge.conform maps it) and `time` (one call on the whole batch, timed).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <sstream>

#include "bindings.hpp"
#include "hinge/io/study_json.hpp"
#include "hinge/study/study.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace hinge::python {
namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

py::array_t<double> as_array(const std::vector<std::array<double, 12>>& hinges) {
  py::array_t<double> x({static_cast<py::ssize_t>(hinges.size()), py::ssize_t{12}});
  double* out = x.mutable_data();
  for (std::size_t i = 0; i < hinges.size(); ++i) std::copy(hinges[i].begin(), hinges[i].end(), out + 12 * i);
  return x;
}

// An outside row from Python: evaluate(X) returns (theta (n,), grad (n, 12), hess (n, 144), status per hinge
// as io::EvalOutput::Status (0 missing, 1 error, 2 non-finite, 3 ok), errors); time(X) the seconds of one
// call of the candidate on the batch X.
study::Outside outside(const std::string& label, const py::function& evaluate, const py::function& time) {
  study::Outside o;
  o.label = label;
  o.evaluate = [evaluate](const std::vector<std::array<double, 12>>& hinges) {
    const py::tuple r = evaluate(as_array(hinges));
    const Array theta = r[0].cast<Array>(), grad = r[1].cast<Array>(), hess = r[2].cast<Array>();
    const auto status = r[3].cast<std::vector<int>>();
    const auto errors = r[4].cast<std::vector<std::string>>();
    const std::size_t n = hinges.size();
    if (static_cast<std::size_t>(theta.size()) != n || static_cast<std::size_t>(grad.size()) != 12 * n ||
        static_cast<std::size_t>(hess.size()) != 144 * n || status.size() != n || errors.size() != n)
      throw py::value_error("study: evaluate must give one row per hinge");
    std::vector<io::EvalOutput> out(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (status[i] < 0 || status[i] > 3) throw py::value_error("study: status must be 0..3");
      out[i].status = static_cast<io::EvalOutput::Status>(status[i]);
      out[i].error = errors[i];
      out[i].theta = theta.data()[i];
      std::copy_n(grad.data() + 12 * i, 12, out[i].grad.begin());
      std::copy_n(hess.data() + 144 * i, 144, out[i].hess.begin());
    }
    return out;
  };
  o.time = [time](const std::vector<std::array<double, 12>>& hinges, int rounds) {
    const py::array_t<double> x = as_array(hinges);
    study::OutsideTiming t;
    try {
      t = study::time_beside_fast(
          [&](const std::vector<std::array<double, 12>>& h) {
            return 1e9 * time(x).cast<double>() / static_cast<double>(h.size());
          },
          hinges, rounds);
    } catch (const py::error_already_set& e) {
      t.rounds.clear();
      t.error = std::string("raised ") + e.what();
    }
    return t;
  };
  return o;
}

// (study.json, study.md) of a study of `methods` in `scalars` (empty: the defaults) and the outside rows
// `candidates`, a list of (label, evaluate, time).
py::tuple run_study(bool quick, double budget, const std::vector<std::string>& methods,
                    const std::vector<std::string>& scalars, bool mesh, const py::list& candidates) {
  study::Options options;
  options.quick = quick;
  options.budget_seconds = budget;
  options.mesh = mesh;
  parsed([&] {
    for (const auto& m : methods) options.methods.push_back(study::check_method(m));
    for (const auto& s : scalars) options.scalars.push_back(parse_scalar_type(s));
    return 0;
  });
  for (const py::handle c : candidates) {
    const py::tuple t = c.cast<py::tuple>();
    options.outside.push_back(outside(t[0].cast<std::string>(), t[1].cast<py::function>(), t[2].cast<py::function>()));
  }
  const study::Study s = parsed([&] { return study::run(options); });
  std::ostringstream json, markdown;
  io::write_study_json(json, s);
  study::write_markdown(markdown, s);
  return py::make_tuple(json.str(), markdown.str());
}

}  // namespace

void bind_study(py::module_& m) {
  m.def("study", &run_study, "quick"_a, "budget"_a, "methods"_a, "scalars"_a, "mesh"_a, "candidates"_a);
}

}  // namespace hinge::python
