// The study's rows in float128 and bin128 (rows.hpp).
#include "rows.hpp"

namespace hinge::study::detail {
template Row measure_row<float128>(methods::Method, const ScalarType&, const Prepared&, double, bool);
template Row measure_row<bin128>(methods::Method, const ScalarType&, const Prepared&, double, bool);
}  // namespace hinge::study::detail
