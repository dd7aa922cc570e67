// The study's rows in mpfr (rows.hpp).
#include "rows.hpp"

namespace hinge::study::detail {
template Row measure_row<mpfr>(methods::Method, const ScalarType&, const Prepared&, double, bool);
}  // namespace hinge::study::detail
