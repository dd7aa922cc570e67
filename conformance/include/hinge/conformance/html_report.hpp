// hinge/conformance/html_report.hpp: the report of a conformance run as one self-contained HTML page
// (`hinge conform --report FILE.html`, report.to_html(path) in Python; docs/conformance.md, "The HTML
// report"): the tier per category, the diagnosis, each case's error against its condition number (an
// inline SVG scatter per output group), for the worst failing case the 12 x 12 map of its Hessian's errors,
// and a reproducer (the 12 inputs, the expected outputs, a pytest snippet). It requests nothing: no
// script, style sheet, image or font from elsewhere; every link is a `#` fragment.
#pragma once

#include <iosfwd>

#include "hinge/conformance/report.hpp"

namespace hinge::conformance {

void write_html_report(std::ostream& out, const Report& report);

}  // namespace hinge::conformance
