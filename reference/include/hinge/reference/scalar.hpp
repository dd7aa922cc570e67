// hinge/reference/scalar.hpp: the scalar types hinge is instantiated for, their names on command lines
// (docs/contract.md: float, double, long-double, float128, bin128, mpfr:BITS), and the glue they need:
// Eigen's NumTraits for Boost.Multiprecision, unqualified math functions, exact conversion from double.
// This is the only header that includes Boost.Multiprecision.
#pragma once

#include <Eigen/Core>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/float128.hpp>
#include <boost/multiprecision/mpfr.hpp>
#include <cmath>
#include <concepts>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace hinge {

// IEEE binary128 through GCC's __float128 (libquadmath).
using float128 = boost::multiprecision::float128;
// IEEE binary128 layout in portable software arithmetic (113-bit significand).
using bin128 = boost::multiprecision::cpp_bin_float_quad;
// MPFR with the precision chosen at run time (set_mpfr_bits); expression templates off, as Eigen needs.
using mpfr = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>,
                                           boost::multiprecision::et_off>;

template <class Scalar>
concept HingeScalar = std::same_as<Scalar, float> || std::same_as<Scalar, double> ||
                      std::same_as<Scalar, long double> || std::same_as<Scalar, float128> ||
                      std::same_as<Scalar, bin128> || std::same_as<Scalar, mpfr>;

// Sets the precision of every mpfr value created afterwards to at least `bits` bits and returns the
// precision obtained. Boost.Multiprecision sets MPFR precision in decimal digits, so the bits obtained
// are the smallest count >= `bits` that a whole number of decimal digits gives (256 -> 257, 113 -> 114).
unsigned set_mpfr_bits(unsigned bits);
// The binary precision of newly created mpfr values.
unsigned mpfr_bits();

// A scalar type named as on the command line.
struct ScalarType {
  enum class Kind { kind_float, kind_double, kind_long_double, kind_float128, kind_bin128, kind_mpfr } kind = Kind::kind_double;
  unsigned mpfr_bits = 0;  // for Kind::kind_mpfr only
  std::string name() const;
};
// Parses "float", "double", "long-double", "float128", "bin128", "mpfr:BITS" (2 <= BITS <= 1000000);
// throws std::invalid_argument with the list of valid names otherwise.
ScalarType parse_scalar_type(std::string_view name);

// Calls f.template operator()<Scalar>() with the Scalar that `type` names (MPFR's precision set first)
// and returns its result: how a run-time choice of scalar type reaches the templates.
template <class F>
decltype(auto) visit_scalar_type(const ScalarType& type, F&& f) {
  using K = ScalarType::Kind;
  switch (type.kind) {
    case K::kind_float: return f.template operator()<float>();
    case K::kind_double: return f.template operator()<double>();
    case K::kind_long_double: return f.template operator()<long double>();
    case K::kind_float128: return f.template operator()<float128>();
    case K::kind_bin128: return f.template operator()<bin128>();
    case K::kind_mpfr: set_mpfr_bits(type.mpfr_bits); return f.template operator()<mpfr>();
  }
  throw std::invalid_argument("unknown scalar type");
}

// The name of Scalar as on the command line.
template <HingeScalar Scalar>
std::string scalar_name() {
  if constexpr (std::same_as<Scalar, float>) return "float";
  else if constexpr (std::same_as<Scalar, double>) return "double";
  else if constexpr (std::same_as<Scalar, long double>) return "long-double";
  else if constexpr (std::same_as<Scalar, float128>) return "float128";
  else if constexpr (std::same_as<Scalar, bin128>) return "bin128";
  else return "mpfr:" + std::to_string(mpfr_bits());
}

// Unit roundoff u = 2^-p of Scalar (p the significand precision; at run time for mpfr).
template <HingeScalar Scalar>
Scalar unit_roundoff() {
  return std::numeric_limits<Scalar>::epsilon() / 2;
}

// Scalar from an exact double. Exact for every type but float, which rounds to nearest.
template <HingeScalar Scalar>
Scalar from_double(double x) {
  return static_cast<Scalar>(x);
}

// The double nearest to x (round to nearest, ties to even), for every Scalar.
template <HingeScalar Scalar>
double to_double(const Scalar& x) {
  if constexpr (std::is_floating_point_v<Scalar>) return static_cast<double>(x);
  else return x.template convert_to<double>();
}

// Math functions called unqualified in the kernels: std's for the built-in types, Boost's (found by
// argument-dependent lookup) for the multiprecision ones.
using std::abs;
using std::atan2;
using std::cos;
using std::sin;
using std::sqrt;
using std::tan;

}  // namespace hinge

// X(type) for every scalar type the library instantiates (explicit instantiations, extern templates).
#define HINGE_FOR_EACH_SCALAR(X) X(float) X(double) X(long double) X(::hinge::float128) X(::hinge::bin128) X(::hinge::mpfr)
