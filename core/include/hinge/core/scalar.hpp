// hinge/core/scalar.hpp: the scalar types hinge is instantiated for, their names on command lines
// (docs/contract.md: float, double, long-double, dd, qd, float128 where built, bin128, mpfr:BITS), and the glue they
// need: Eigen's NumTraits for Boost.Multiprecision and for QD, unqualified math functions, exact
// conversion from double, pi. This is the only header that includes Boost.Multiprecision or QD.
//
// QD (libqd, Hida, Li & Bailey) is configured here, before its headers: its inline arithmetic with the
// IEEE-style addition (fl(a + b) = (1 + d)(a + b), |d| <= eps, QD_IEEE_ADD) instead of Debian's default
// Cray-style one (fl(a + b) = (1 + d1) a + (1 + d2) b), which loses every digit where a and b cancel, as
// they do in the edge differences and the cross products of thin triangles; and its exact multiplication
// and division (QD_SLOPPY_MUL, QD_SLOPPY_DIV off). The library's own compiled functions (sqrt, atan2,
// sin, cos) keep Debian's settings: a few units of their precision. Its numeric_limits derives from
// double's, with epsilon() = 2^-104 (dd) and 2^-209 (qd): unit_roundoff below is half of that.
#pragma once

#include <qd/qd_config.h>
#undef QD_SLOPPY_MUL
#undef QD_SLOPPY_DIV
#ifndef QD_IEEE_ADD
#define QD_IEEE_ADD 1
#endif
#include <qd/dd_real.h>
#include <qd/qd_real.h>

#include <Eigen/Core>
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/mpfr.hpp>

#include "hinge/core/scalar_list.hpp"  // HINGE_HAVE_FLOAT128, HINGE_FOR_EACH_SCALAR (generated)
#if HINGE_HAVE_FLOAT128
#include <boost/multiprecision/float128.hpp>
#endif
#include <cmath>
#include <concepts>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

namespace hinge {

#if HINGE_HAVE_FLOAT128
// IEEE binary128 through GCC's __float128 (libquadmath; x86 only).
using float128 = boost::multiprecision::float128;
#endif
// IEEE binary128 layout in portable software arithmetic (113-bit significand).
using bin128 = boost::multiprecision::cpp_bin_float_quad;
// MPFR with the precision chosen at run time (set_mpfr_bits); expression templates off, as Eigen needs.
using mpfr = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<0>, boost::multiprecision::et_off>;

// QD's double-double (about 106 bits) and quad-double (about 212 bits), in the global namespace.
using dd = ::dd_real;
using qd = ::qd_real;

template <class Scalar>
concept HingeScalar = std::same_as<Scalar, float> || std::same_as<Scalar, double> ||
    std::same_as<Scalar, long double> || std::same_as<Scalar, dd> || std::same_as<Scalar, qd> ||
#if HINGE_HAVE_FLOAT128
    std::same_as<Scalar, float128> ||
#endif
    std::same_as<Scalar, bin128> || std::same_as<Scalar, mpfr>;
// QD's types (their own conversions, constants and limits).
template <class Scalar>
concept QdScalar = std::same_as<Scalar, dd> || std::same_as<Scalar, qd>;

// Sets the precision of every mpfr value created afterwards to at least `bits` bits and returns the
// precision obtained. Boost.Multiprecision sets MPFR precision in decimal digits, so the bits obtained
// are the smallest count >= `bits` that a whole number of decimal digits gives (256 -> 257, 113 -> 114).
unsigned set_mpfr_bits(unsigned bits);
// The binary precision of newly created mpfr values.
unsigned mpfr_bits();

// A scalar type named as on the command line.
struct ScalarType {
  enum class Kind {
    kind_float,
    kind_double,
    kind_long_double,
    kind_dd,
    kind_qd,
    kind_float128,
    kind_bin128,
    kind_mpfr
  } kind = Kind::kind_double;
  unsigned mpfr_bits = 0;  // for Kind::kind_mpfr only
  std::string name() const;
};
// Parses "float", "double", "long-double", "dd", "qd", "float128", "bin128", "mpfr:BITS" (2 <= BITS <= 1000000);
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
    case K::kind_dd: return f.template operator()<dd>();
    case K::kind_qd: return f.template operator()<qd>();
    case K::kind_float128:
#if HINGE_HAVE_FLOAT128
      return f.template operator()<float128>();
#else
      break;  // not built: parse_scalar_type refuses the name
#endif
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
  else if constexpr (std::same_as<Scalar, dd>) return "dd";
  else if constexpr (std::same_as<Scalar, qd>) return "qd";
#if HINGE_HAVE_FLOAT128
  else if constexpr (std::same_as<Scalar, float128>) return "float128";
#endif
  else if constexpr (std::same_as<Scalar, bin128>) return "bin128";
  else return "mpfr:" + std::to_string(mpfr_bits());
}

// Unit roundoff u = 2^-p of Scalar (p the significand precision; at run time for mpfr).
template <HingeScalar Scalar>
Scalar unit_roundoff() {
  return Scalar(std::numeric_limits<Scalar>::epsilon()) / 2;
}

// pi rounded to Scalar.
template <HingeScalar Scalar>
Scalar pi_of() {
  if constexpr (QdScalar<Scalar>) return Scalar::_pi;
  else return boost::math::constants::pi<Scalar>();
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
  else if constexpr (QdScalar<Scalar>) return ::to_double(x);  // QD's: hi + lo rounded once (dd: the hi part)
  else return x.template convert_to<double>();
}

// x as an mpfr value at the current precision (mpfr_bits(): exact when that is at least Scalar's).
template <HingeScalar Scalar>
mpfr to_mpfr(const Scalar& x) {
  if constexpr (std::same_as<Scalar, mpfr>) return x;
  else if constexpr (std::same_as<Scalar, dd>) return mpfr(x.x[0]) + mpfr(x.x[1]);
  else if constexpr (std::same_as<Scalar, qd>) return ((mpfr(x.x[0]) + mpfr(x.x[1])) + mpfr(x.x[2])) + mpfr(x.x[3]);
  else return mpfr(x);
}

// The mpfr value x rounded to Scalar (dd and qd: component by component, each the rounded remainder).
template <HingeScalar Scalar>
Scalar from_mpfr(const mpfr& x) {
  if constexpr (std::same_as<Scalar, mpfr>) return x;
  else if constexpr (QdScalar<Scalar>) {
    constexpr int parts = std::same_as<Scalar, dd> ? 2 : 4;
    double c[4] = {0, 0, 0, 0};
    mpfr rest = x;
    for (int i = 0; i < parts; ++i) {
      c[i] = rest.template convert_to<double>();
      rest -= c[i];
    }
    if constexpr (parts == 2) return dd(c[0], c[1]);
    else return qd(c[0], c[1], c[2], c[3]);
  } else {
    return static_cast<Scalar>(x);
  }
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

// Eigen's traits for QD's types (the only glue Eigen needs: Boost.Multiprecision brings its own).
namespace Eigen {
template <class Q>
struct QdNumTraits : GenericNumTraits<Q> {
  using Real = Q;
  using NonInteger = Q;
  using Literal = Q;
  using Nested = Q;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 2,
    AddCost = 8,
    MulCost = 16
  };
  static Q epsilon() { return Q(std::numeric_limits<Q>::epsilon()); }
  static Q dummy_precision() { return Q(std::numeric_limits<Q>::epsilon()) * 1024; }
  static Q highest() { return std::numeric_limits<Q>::max(); }
  static Q lowest() { return -std::numeric_limits<Q>::max(); }
  static int digits10() { return std::numeric_limits<Q>::digits10; }
};
template <>
struct NumTraits<::dd_real> : QdNumTraits<::dd_real> {};
template <>
struct NumTraits<::qd_real> : QdNumTraits<::qd_real> {};
}  // namespace Eigen
