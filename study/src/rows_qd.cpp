// The study's rows in QD's dd and qd (rows.hpp).
#include "rows.hpp"

namespace hinge::study::detail {
template Row measure_row<dd>(methods::Method, const ScalarType&, const Prepared&, double, bool);
template Row measure_row<qd>(methods::Method, const ScalarType&, const Prepared&, double, bool);
}  // namespace hinge::study::detail
