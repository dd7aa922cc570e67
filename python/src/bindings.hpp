// The parts of the module hinge._hinge defined in their own translation units (module.cpp defines the
// module and the evaluation functions).
#pragma once

#include <pybind11/pybind11.h>

namespace hinge::python {

// The conformance kit's compiled part (conformance.cpp): the committed sets and the graded report.
void bind_conformance(pybind11::module_& m);

}  // namespace hinge::python
