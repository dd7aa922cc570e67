// theta in the faithful mode (faithful_theta.hpp).
#include "faithful_theta.hpp"

#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "hinge/core/scalar.hpp"

namespace hinge::fast::detail {
namespace {

static_assert(sizeof(long double) > sizeof(double), "the faithful mode's theta needs x87 long double (64 bits)");

long double value(const std::array<double, 2>& dd) { return static_cast<long double>(dd[0]) + dd[1]; }

// The accurate paths: 113 bits. GCC's __float128 (libquadmath's sqrtq and atan2q) where it is built (x86);
// elsewhere long double where it is binary128 (aarch64), else Boost's software binary128.
#if HINGE_HAVE_FLOAT128
using Quad = float128;
#elif LDBL_MANT_DIG == 113
using Quad = long double;
#else
using Quad = bin128;
#endif
using std::ldexp;

Quad quad(const std::array<double, 2>& dd) { return Quad(dd[0]) + Quad(dd[1]); }

// The coordinates of x as integers times 2^E, E the exponent of the lowest bit any of them has.
struct Integers {
  mpz_t v[12];
  long E = 0;
  explicit Integers(const std::array<double, 12>& x) {
    long lowest = 0;
    bool any = false;
    for (double c : x)
      if (c != 0) {
        int e;
        std::frexp(c, &e);  // c = f 2^e, f in [0.5, 1): its lowest bit is at or above 2^(e - 53)
        lowest = any ? std::min(lowest, static_cast<long>(e) - 53) : static_cast<long>(e) - 53;
        any = true;
      }
    E = lowest;
    for (int i = 0; i < 12; ++i) {
      mpz_init(v[i]);
      if (x[i] == 0) continue;
      int e;
      const double f = std::frexp(x[i], &e);
      mpz_set_si(v[i], static_cast<long>(std::ldexp(f, 53)));  // exact: 53 bits
      mpz_mul_2exp(v[i], v[i], static_cast<mp_bitcnt_t>(e - 53 - E));
    }
  }
  ~Integers() {
    for (auto& z : v) mpz_clear(z);
  }
  Integers(const Integers&) = delete;
  Integers& operator=(const Integers&) = delete;
};

}  // namespace

ScaledDeterminant exact_hinge_determinant(const std::array<double, 12>& x, int exponent) {
  const Integers c(x);
  mpz_t p[3], q[3], r[3], t, D;
  for (int k = 0; k < 3; ++k) {
    mpz_inits(p[k], q[k], r[k], static_cast<mpz_ptr>(nullptr));
    mpz_sub(p[k], c.v[6 + k], c.v[3 + k]);
    mpz_sub(q[k], c.v[k], c.v[3 + k]);
    mpz_sub(r[k], c.v[9 + k], c.v[3 + k]);
  }
  mpz_inits(t, D, static_cast<mpz_ptr>(nullptr));
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    mpz_mul(t, q[i], r[j]);
    mpz_submul(t, q[j], r[i]);
    mpz_submul(D, t, p[k]);
  }
  // D 2^(3E - 3 exponent) = (hi + mid + lo) 2^e, the sum in [1/2, 1): its nearest double, the nearest to
  // the rest, and so on, the exponent apart (D itself may lie outside double's range: 2^1140 on a nearly
  // flat hinge at 2^400).
  mpfr_t w;
  mpfr_init2(w, 160);
  mpfr_set_z_2exp(w, D, 3 * (c.E - exponent), MPFR_RNDN);
  ScaledDeterminant result;
  if (!mpfr_zero_p(w)) {
    result.e = mpfr_get_exp(w);
    mpfr_set_exp(w, 0);
    for (double* part : {&result.hi, &result.mid, &result.lo}) {
      *part = mpfr_get_d(w, MPFR_RNDN);
      mpfr_sub_d(w, w, *part, MPFR_RNDN);
    }
  }
  mpfr_clear(w);
  for (int k = 0; k < 3; ++k) mpz_clears(p[k], q[k], r[k], static_cast<mpz_ptr>(nullptr));
  mpz_clears(t, D, static_cast<mpz_ptr>(nullptr));
  return result;
}

namespace {

// theta nearly flat: sin theta = |D| l_0^3 K K~, cos theta = 1 - |n - n~|^2 / 2, in float128, D exact
// (exact_hinge_determinant).
double near_flat_theta(const std::array<double, 12>& x, int exponent, const FaithfulTheta& f) {
  const ScaledDeterminant D = exact_hinge_determinant(x, exponent);
  const Quad l0_squared = quad(f.l0_squared);
  const Quad sine = ldexp(abs((Quad(D.hi) + Quad(D.mid)) + Quad(D.lo)), static_cast<int>(D.e)) *
                    (l0_squared * sqrt(l0_squared)) * (quad(f.K) * quad(f.K_lower));
  const Quad cosine = 1 - quad(f.minus2) / 2;
  return static_cast<double>(atan2(sine, cosine));
}

// 2 atan2(|n - n~|, |n + n~|) in float128 from the double-double squares.
double accurate_theta(const FaithfulTheta& f) {
  return static_cast<double>(2 * atan2(sqrt(quad(f.minus2)), sqrt(quad(f.plus2))));
}

}  // namespace

double faithful_theta(const std::array<double, 12>& x, int sign, int exponent, const FaithfulTheta& f) {
  double theta;
  if (f.minus2[0] < 0x1p-80) {  // |theta| < 2^-40 (|n - n~| = 2 sin(theta/2))
    theta = near_flat_theta(x, exponent, f);
  } else {
    const long double t = 2 * std::atan2(std::sqrt(value(f.minus2)), std::sqrt(value(f.plus2)));
    // Its relative error: below 5 2^-64 < 2^-61 from the long double steps (two conversions and square
    // roots, 1.5 2^-64 each in m and p; the atan2 within 2^-63), and 2^-99 / theta from the double-double
    // normals' difference (a few units of 2^-104 absolute).
    const long double bound = t * (0x1p-61L + 0x1p-99L / t);
    if (static_cast<double>(t - bound) == static_cast<double>(t + bound)) theta = static_cast<double>(t);  // decided
    else if (t < 0x1p-20L) theta = near_flat_theta(x, exponent, f);  // the normals are not accurate enough to decide
    else theta = accurate_theta(f);
  }
  return std::copysign(theta, static_cast<double>(sign));
}

}  // namespace hinge::fast::detail
