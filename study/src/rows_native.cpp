// The study's rows in float, double and long double (rows.hpp).
#include "rows.hpp"

namespace hinge::study::detail {
template Row measure_row<float>(methods::Method, const ScalarType&, const Prepared&, double, bool);
template Row measure_row<double>(methods::Method, const ScalarType&, const Prepared&, double, bool);
template Row measure_row<long double>(methods::Method, const ScalarType&, const Prepared&, double, bool);
}  // namespace hinge::study::detail
