// hinge._hinge: the Python module of docs/python.md (contract, "Python"). Argument checking and
// conversion between NumPy and the library's types; every number comes from the library, as the
// commands get it (hinge::methods, hinge::oracle, io::transform_hinge_lines). The GIL is released while
// the library computes.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bindings.hpp"
#include "hinge/conformance/certified_line.hpp"
#include "hinge/core/bending_problem.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/core/mesh.hpp"
#include "hinge/fast/faithful.hpp"
#include "hinge/io/jsonl.hpp"
#include "hinge/methods/methods.hpp"
#include "hinge/oracle/oracle.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

using hinge::python::parsed;
using Hinges = py::array_t<double, py::array::c_style>;

// theta (n,), grad (n, 12), hess (n, 12, 12), error (n: None or why), for eval and oracle.
struct Result {
  py::array_t<double> theta, grad, hess;
  py::list error;
  py::list uncertified;  // oracle only: per hinge None or the outputs not certified within the cap
};

// `x` as a C-contiguous float64 array of shape (n, 12); ValueError naming what is wrong.
Hinges as_hinges(const py::object& x) {
  py::array a;
  try {
    a = py::module_::import("numpy").attr("ascontiguousarray")(x, "dtype"_a = "float64");
  } catch (py::error_already_set& e) {
    throw py::value_error(std::string("x must be convertible to a float64 array: ") + e.what());
  }
  if (a.ndim() == 1 && a.shape(0) == 12) a = a.attr("reshape")(1, 12);
  if (a.ndim() != 2 || a.shape(1) != 12) {
    std::string shape = py::str(a.attr("shape"));
    throw py::value_error("x must have shape (n, 12) or (12,) (x0.x, x0.y, ..., x3.z per hinge); got " + shape);
  }
  return a.cast<Hinges>();
}

// Runs evaluate(i, x_i, theta, grad, hess) for every hinge with the GIL released; a hinge whose
// evaluation throws InputError or DomainError gets NaN rows and the message in `error`.
template <class Evaluate>
Result run_hinges(const py::object& x_object, Evaluate&& evaluate) {
  const Hinges x = as_hinges(x_object);
  const py::ssize_t rows = x.shape(0);
  const auto n = static_cast<std::size_t>(rows);
  Result r{py::array_t<double>({rows}), py::array_t<double>({rows, py::ssize_t{12}}),
           py::array_t<double>({rows, py::ssize_t{12}, py::ssize_t{12}}), py::list(), py::list()};
  std::vector<std::optional<std::string>> errors(n);
  {
    const double* in = x.data();
    double* theta = r.theta.mutable_data();
    double* grad = r.grad.mutable_data();
    double* hess = r.hess.mutable_data();
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i) {
      std::array<double, 12> xi;
      std::copy_n(in + 12 * i, 12, xi.begin());
      try {
        evaluate(i, xi, theta + i, grad + 12 * i, hess + 144 * i);
      } catch (const hinge::InputError& e) {
        errors[i] = e.what();
      } catch (const hinge::DomainError& e) {
        errors[i] = e.what();
      }
      if (errors[i]) {
        theta[i] = std::nan("");
        std::fill_n(grad + 12 * i, 12, std::nan(""));
        std::fill_n(hess + 144 * i, 144, std::nan(""));
      }
    }
  }
  for (auto& e : errors) r.error.append(e ? py::object(py::str(*e)) : py::object(py::none()));
  return r;
}

template <class Rounded>
void store(const Rounded& v, double* theta, double* grad, double* hess) {
  *theta = v.theta;
  std::copy(v.grad.begin(), v.grad.end(), grad);
  std::copy(v.hess.begin(), v.hess.end(), hess);
}

// Arguments of the wrong Python type are ValueErrors naming the argument (contract, "Python"), not
// pybind11's TypeError.
std::string as_name(const py::object& o, const char* what) {
  if (!py::isinstance<py::str>(o))
    throw py::value_error(std::string(what) + " must be a string; got " +
                          std::string(py::str(py::type::of(o).attr("__name__"))));
  return o.cast<std::string>();
}
double as_number(const py::object& o, const char* what) {
  if (py::isinstance<py::bool_>(o) ||
      !(py::isinstance<py::float_>(o) || py::isinstance<py::int_>(o) || py::hasattr(o, "__float__")))
    throw py::value_error(std::string(what) + " must be a number; got " +
                          std::string(py::str(py::type::of(o).attr("__name__"))));
  try {
    return py::float_(o).cast<double>();
  } catch (py::error_already_set& e) {
    throw py::value_error(std::string(what) + " must be a number: " + e.what());
  }
}
// An integer argument (its range is checked by the caller); a ValueError naming it for any other type.
long long as_integer(const py::object& o, const char* what) {
  if (py::isinstance<py::bool_>(o) || !py::hasattr(o, "__index__"))
    throw py::value_error(std::string(what) + " must be an integer; got " +
                          std::string(py::str(py::type::of(o).attr("__name__"))));
  const py::int_ value(o);
  const py::int_ largest(std::numeric_limits<long long>::max()), smallest(std::numeric_limits<long long>::min());
  return value > largest    ? std::numeric_limits<long long>::max()
         : value < smallest ? std::numeric_limits<long long>::min()
                            : value.cast<long long>();
}
hinge::methods::Method as_method(const py::object& o) {
  return parsed([&] { return hinge::methods::parse_method(as_name(o, "method")); });
}
hinge::ScalarType as_scalar(const py::object& o) {
  return parsed([&] { return hinge::parse_scalar_type(as_name(o, "scalar")); });
}

// Boost's MPFR types (1.74) keep their default precision for the whole process, and the mpfr:BITS scalar
// types set it before each evaluation: with the GIL released, two Python threads using two precisions
// would change each other's. Evaluations in an mpfr type hold this lock (the others run concurrently).
std::mutex mpfr_precision;
std::unique_lock<std::mutex> lock_if_mpfr(const hinge::ScalarType& scalar) {
  if (scalar.kind == hinge::ScalarType::Kind::kind_mpfr) return std::unique_lock<std::mutex>(mpfr_precision);
  return {};
}

Result eval(const py::object& x, const py::object& method_name, const py::object& scalar_name, bool faithful) {
  const auto method = as_method(method_name);
  const auto scalar = as_scalar(scalar_name);
  if (faithful && (method != hinge::methods::Method::fast || scalar.kind != hinge::ScalarType::Kind::kind_double))
    throw py::value_error("faithful=True needs method='fast' and scalar='double'");
  std::unique_lock<std::mutex> lock;
  return run_hinges(x, [&](std::size_t i, const std::array<double, 12>& xi, double* t, double* g, double* h) {
    if (i == 0) lock = lock_if_mpfr(scalar);  // without the GIL (run_hinges released it)
    store(faithful ? hinge::fast::faithful_derivatives_rounded(xi) : hinge::methods::evaluate_hinge(method, scalar, xi),
          t, g, h);
  });
}

Result oracle(const py::object& x) {
  std::vector<std::vector<std::string>> uncertified;
  Result r = run_hinges(x, [&](std::size_t i, const std::array<double, 12>& xi, double* t, double* g, double* h) {
    const auto c = hinge::oracle::certified_theta_derivatives(xi);
    store(c, t, g, h);
    if (uncertified.size() <= i) uncertified.resize(i + 1);
    for (const auto& u : c.uncertified) uncertified[i].push_back(u.output);
  });
  uncertified.resize(static_cast<std::size_t>(r.theta.shape(0)));
  for (const auto& u : uncertified) r.uncertified.append(u.empty() ? py::object(py::none()) : py::cast(u));
  return r;
}

// The (m, 3) faces, 0-based indices into `vertex_count` vertices, checked before any conversion (an
// unsigned index above 2^63 is named as given); ValueError naming the argument.
std::vector<std::array<hinge::Index, 3>> as_faces(const py::object& faces, std::size_t vertex_count) {
  py::array f;
  try {
    f = py::module_::import("numpy").attr("asarray")(faces);
  } catch (py::error_already_set& e) {
    throw py::value_error(std::string("faces must be an (m, 3) array of integers: ") + e.what());
  }
  if (f.ndim() != 2 || f.shape(1) != 3)
    throw py::value_error("faces must have shape (m, 3); got " + std::string(py::str(f.attr("shape"))));
  if (f.shape(0) == 0) throw py::value_error("faces is empty: a mesh needs at least one face");
  const std::string kind = py::str(f.dtype().attr("kind"));
  if (kind != "i" && kind != "u")
    throw py::value_error("faces must hold integers (0-based vertex indices); got dtype " +
                          std::string(py::str(f.dtype())));
  const std::string type = kind == "u" ? "uint64" : "int64";
  const py::array wide = py::module_::import("numpy").attr("ascontiguousarray")(f, "dtype"_a = type);
  std::vector<std::array<hinge::Index, 3>> out(static_cast<std::size_t>(f.shape(0)));
  for (std::size_t face = 0; face < out.size(); ++face)
    for (std::size_t c = 0; c < 3; ++c) {
      std::string shown;
      bool inside;
      std::uint64_t index;
      if (kind == "u") {
        index = static_cast<const std::uint64_t*>(wide.data())[3 * face + c];
        inside = index < vertex_count;
        shown = std::to_string(index);
      } else {
        const std::int64_t signed_index = static_cast<const std::int64_t*>(wide.data())[3 * face + c];
        inside = signed_index >= 0 && static_cast<std::uint64_t>(signed_index) < vertex_count;
        index = static_cast<std::uint64_t>(signed_index);
        shown = std::to_string(signed_index);
      }
      if (!inside)
        throw py::value_error("faces[" + std::to_string(face) + "] refers to vertex " + shown + ", but there are " +
                              std::to_string(vertex_count) + " vertices (0-based)");
      out[face][c] = static_cast<hinge::Index>(index);
    }
  return out;
}

// The (n, 3) vertices of a mesh (`name`: "vertices" or "rest"); ValueError naming the argument.
std::vector<std::array<double, 3>> as_vertices(const py::object& vertices, const char* name) {
  py::array v;
  try {
    v = py::module_::import("numpy").attr("ascontiguousarray")(vertices, "dtype"_a = "float64");
  } catch (py::error_already_set& e) {
    throw py::value_error(std::string(name) + " must be convertible to a float64 array: " + e.what());
  }
  if (v.ndim() != 2 || v.shape(1) != 3)
    throw py::value_error(std::string(name) + " must have shape (n, 3); got " + std::string(py::str(v.attr("shape"))));
  const auto pv = v.cast<py::array_t<double, py::array::c_style>>();
  std::vector<std::array<double, 3>> out(static_cast<std::size_t>(pv.shape(0)));
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c) {
      const double value = pv.data()[3 * i + c];
      if (!std::isfinite(value)) throw py::value_error(std::string(name) + "[" + std::to_string(i) + "] is not finite");
      out[i][c] = value;
    }
  return out;
}

py::tuple hessian(const py::object& vertices, const py::object& faces_object, const py::object& rest_object,
                  const py::object& energy, const py::object& k_object, const py::object& method_name,
                  const py::object& threads_object, const py::object& scalar_name, bool allow_no_hinges) {
  const auto method = as_method(method_name);
  const auto scalar = as_scalar(scalar_name);
  const double k = as_number(k_object, "k");
  const std::string energy_name = as_name(energy, "energy");
  const hinge::EnergyParameters parameters = parsed([&] {
    return hinge::bending_problem({k, "k="}, energy_name, "energy=").parameters();
  });
  const long long requested_threads = as_integer(threads_object, "threads");
  const int threads = parsed([&] { return hinge::resolve_threads(requested_threads, "threads="); });
  hinge::Mesh deformed;
  deformed.vertices = as_vertices(vertices, "vertices");
  deformed.faces = as_faces(faces_object, deformed.vertices.size());
  std::optional<hinge::Mesh> rest;
  if (!rest_object.is_none()) {
    rest.emplace();
    rest->vertices = as_vertices(rest_object, "rest");
    if (rest->vertices.size() != deformed.vertices.size())
      throw py::value_error("rest has " + std::to_string(rest->vertices.size()) + " vertices, vertices has " +
                            std::to_string(deformed.vertices.size()));
    rest->faces = deformed.faces;
  }
  hinge::RoundedMesh result;
  try {
    py::gil_scoped_release release;
    const auto lock = lock_if_mpfr(scalar);
    const hinge::Topology topology = hinge::build_topology(deformed);
    hinge::check_bending_mesh(topology, deformed, rest ? &*rest : nullptr,
                              {"", "rest=", "allow_no_hinges=True", allow_no_hinges});
    hinge::methods::MeshInput input{&deformed,  rest ? &*rest : &deformed, &topology,
                                    parameters, hinge::want_all,           threads};
    result = hinge::methods::evaluate_mesh(method, scalar, input);
  } catch (const hinge::InputError& e) {
    throw py::value_error(e.what());
  } catch (const hinge::DomainError& e) {
    PyErr_SetString(PyExc_OverflowError, e.what());
    throw py::error_already_set();
  }
  // The full symmetric matrix from the upper triangle: (i, j) and (j, i) off the diagonal.
  const auto& upper = result.hessian;
  std::vector<double> data;
  std::vector<std::int64_t> rows, cols;
  data.reserve(2 * static_cast<std::size_t>(upper.nonZeros()));
  for (int j = 0; j < upper.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(upper, j); it; ++it) {
      rows.push_back(it.row()), cols.push_back(it.col()), data.push_back(it.value());
      if (it.row() != it.col()) rows.push_back(it.col()), cols.push_back(it.row()), data.push_back(it.value());
    }
  const auto size = static_cast<std::int64_t>(3 * deformed.vertices.size());
  py::object csr =
      py::module_::import("scipy.sparse")
          .attr("csr_matrix")(py::make_tuple(py::array(py::cast(data)),
                                             py::make_tuple(py::array(py::cast(rows)), py::array(py::cast(cols)))),
                              "shape"_a = py::make_tuple(size, size));
  return py::make_tuple(result.energy, py::array(py::cast(result.gradient)), csr);
}

// The shard of a JSON Lines file that hinge.distributed gives a worker: the output bytes of `hinge eval`
// or `hinge oracle` for it (io::transform_hinge_lines, lines numbered from first_line), and the number of
// outputs and hinges the oracle could not certify.
py::tuple stream(const std::string& command, const py::bytes& input, long first_line, const py::object& method_name,
                 const py::object& scalar_name, bool report_precision, unsigned start_bits, unsigned max_bits) {
  if (command != "eval" && command != "oracle") throw py::value_error("command must be 'eval' or 'oracle'");
  const auto method = as_method(method_name);
  const auto scalar = as_scalar(scalar_name);
  std::istringstream in(static_cast<std::string>(input));
  std::ostringstream out;
  std::size_t flagged_outputs = 0, flagged_hinges = 0;
  {
    py::gil_scoped_release release;
    const auto lock = lock_if_mpfr(scalar);
    hinge::oracle::Options options;
    options.start_bits = start_bits;
    options.max_bits = max_bits;
    if (command == "eval")
      hinge::io::transform_hinge_lines(
          in, out, first_line,
          [&](const std::string& id, const std::array<double, 12>& x) {
            return hinge::io::result_line(id, hinge::methods::evaluate_hinge(method, scalar, x));
          },
          [] {});
    else
      hinge::io::transform_hinge_lines(
          in, out, first_line,
          [&](const std::string& id, const std::array<double, 12>& x) {
            const auto c = hinge::oracle::certified_theta_derivatives(x, options);
            flagged_outputs += c.uncertified.size();
            flagged_hinges += c.uncertified.empty() ? 0 : 1;
            return hinge::conformance::certified_line(id, c, report_precision);
          },
          [] {});
  }
  return py::make_tuple(py::bytes(out.str()), flagged_outputs, flagged_hinges);
}

}  // namespace

PYBIND11_MODULE(_hinge, m) {
  m.doc() = "The compiled part of the hinge module (docs/python.md); use the functions of `hinge`.";
  py::class_<Result>(m, "Result",
                     "theta (n,), grad (n, 12), hess (n, 12, 12) as float64, error: n entries, None or why")
      .def_readonly("theta", &Result::theta, "theta per hinge, in (-pi, pi] (NaN where error is not None)")
      .def_readonly("grad", &Result::grad, "grad theta per hinge, (n, 12): x0.x, x0.y, ..., x3.z")
      .def_readonly("hess", &Result::hess, "Hess theta per hinge, (n, 12, 12)")
      .def_readonly("error", &Result::error, "per hinge None, or the reason it could not be evaluated")
      .def_readonly("uncertified", &Result::uncertified,
                    "oracle only: per hinge None, or the outputs not certified within the precision cap")
      .def("__len__", [](const Result& r) { return r.theta.shape(0); })
      .def("__repr__",
           [](const Result& r) { return "<hinge.Result of " + std::to_string(r.theta.shape(0)) + " hinges>"; });
  const hinge::oracle::Options defaults;
  m.def("eval", &eval, "x"_a, "method"_a = "fast", "scalar"_a = "double", "faithful"_a = false);
  m.def("oracle", &oracle, "x"_a);
  m.def("hessian", &hessian, "vertices"_a, "faces"_a, "rest"_a = py::none(), "energy"_a = "tan", "k"_a = 1.0,
        "method"_a = "fast", "threads"_a = 0, "scalar"_a = "double", "allow_no_hinges"_a = false);
  m.def("stream", &stream, "command"_a, "input"_a, "first_line"_a = 1, "method"_a = "reference", "scalar"_a = "double",
        "report_precision"_a = false, "start_bits"_a = defaults.start_bits, "max_bits"_a = defaults.max_bits);
  hinge::python::bind_conformance(m);
  hinge::python::bind_mesh_conformance(m);
#if HINGE_PYTHON_STUDY
  hinge::python::bind_study(m);
#endif
}
