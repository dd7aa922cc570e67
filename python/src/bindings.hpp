// The parts of the module hinge._hinge defined in their own translation units (module.cpp defines the
// module and the evaluation functions).
#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>

namespace hinge::python {

// f(), with std::invalid_argument (an unknown method, scalar, energy, dtype or depth) as ValueError.
template <class F>
decltype(auto) parsed(F&& f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw pybind11::value_error(e.what());
  }
}

// The conformance kit's compiled part (conformance.cpp): the committed sets and the graded report.
void bind_conformance(pybind11::module_& m);
// The whole-mesh conformance's compiled part (mesh_conformance.cpp): certified mesh values and their comparison.
void bind_mesh_conformance(pybind11::module_& m);
// The study with Python callables as outside rows (study.cpp; built where hinge::study is).
void bind_study(pybind11::module_& m);

}  // namespace hinge::python
