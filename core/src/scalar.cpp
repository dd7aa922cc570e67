// Scalar-type names and MPFR precision (hinge/core/scalar.hpp).
#include "hinge/core/scalar.hpp"

#include <boost/multiprecision/detail/digits.hpp>
#include <charconv>
#include <stdexcept>

namespace hinge {

unsigned set_mpfr_bits(unsigned bits) {
  unsigned digits10 = 1;
  while (boost::multiprecision::detail::digits10_2_2(digits10) < bits) ++digits10;
  mpfr::default_precision(digits10);
  return mpfr_bits();
}

unsigned mpfr_bits() {
  return static_cast<unsigned>(boost::multiprecision::detail::digits10_2_2(mpfr::default_precision()));
}

std::string ScalarType::name() const {
  switch (kind) {
    case Kind::kind_float: return "float";
    case Kind::kind_double: return "double";
    case Kind::kind_long_double: return "long-double";
    case Kind::kind_dd: return "dd";
    case Kind::kind_qd: return "qd";
    case Kind::kind_float128: return "float128";
    case Kind::kind_bin128: return "bin128";
    case Kind::kind_mpfr: return "mpfr:" + std::to_string(mpfr_bits);
  }
  return "?";
}

ScalarType parse_scalar_type(std::string_view name) {
  using K = ScalarType::Kind;
  if (name == "float") return {K::kind_float, 0};
  if (name == "double") return {K::kind_double, 0};
  if (name == "long-double") return {K::kind_long_double, 0};
  if (name == "dd") return {K::kind_dd, 0};
  if (name == "qd") return {K::kind_qd, 0};
  if (name == "float128") {
    if (HINGE_HAVE_FLOAT128) return {K::kind_float128, 0};
    throw std::invalid_argument(
        "scalar type 'float128' is not in this build (GCC's __float128: x86 only, and "
        "HINGE_FLOAT128=ON)");
  }
  if (name == "bin128") return {K::kind_bin128, 0};
  if (name.starts_with("mpfr:")) {
    std::string_view digits = name.substr(5);
    unsigned bits = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), bits);
    if (ec == std::errc() && end == digits.data() + digits.size() && bits >= 2 && bits <= 1000000)
      return {K::kind_mpfr, bits};
  }
  throw std::invalid_argument("unknown scalar type '" + std::string(name) +
                              "': expected float, double, long-double, dd, qd, float128, bin128 or mpfr:BITS "
                              "(2 <= BITS <= 1000000)");
}

}  // namespace hinge
