// oracle/src/interval.hpp: a thin RAII value type over an MPFI interval (private to hinge::oracle).
// Every operation rounds outward (MPFI's guarantee): the result contains every value the operation can
// take on the operands. New intervals get the working precision of the innermost WorkingPrecision scope.
#pragma once

#include <gmpxx.h>
#include <mpfi.h>
#include <mpfr.h>

#include <string>

namespace hinge::oracle::detail {

inline thread_local mpfr_prec_t working_bits = 128;

// Sets the precision of intervals created in its lifetime.
class WorkingPrecision {
 public:
  explicit WorkingPrecision(mpfr_prec_t bits) : saved_(working_bits) { working_bits = bits; }
  ~WorkingPrecision() { working_bits = saved_; }
  WorkingPrecision(const WorkingPrecision&) = delete;
  WorkingPrecision& operator=(const WorkingPrecision&) = delete;

 private:
  mpfr_prec_t saved_;
};

class Interval {
 public:
  Interval() { mpfi_init2(v_, working_bits); }  // NaN until set
  explicit Interval(const mpz_class& z) : Interval() { mpfi_set_z(v_, z.get_mpz_t()); }
  explicit Interval(double d) : Interval() { mpfi_set_d(v_, d); }  // exact (working_bits >= 53)
  ~Interval() { mpfi_clear(v_); }
  // Copies keep the source's precision; moves swap the limbs.
  Interval(const Interval& o) {
    mpfi_init2(v_, mpfi_get_prec(o.v_));
    mpfi_set(v_, o.v_);
  }
  Interval(Interval&& o) noexcept : Interval() { mpfi_swap(v_, o.v_); }
  Interval& operator=(const Interval& o) {
    if (this != &o) {
      mpfi_set_prec(v_, mpfi_get_prec(o.v_));
      mpfi_set(v_, o.v_);
    }
    return *this;
  }
  Interval& operator=(Interval&& o) noexcept {
    mpfi_swap(v_, o.v_);
    return *this;
  }

  mpfi_ptr get() { return v_; }
  mpfi_srcptr get() const { return v_; }

  static Interval pi() {
    Interval r;
    mpfi_const_pi(r.v_);
    return r;
  }
  // A point interval [0, 0].
  static Interval zero() {
    Interval r;
    mpfi_set_ui(r.v_, 0);
    return r;
  }
  bool is_exact_zero() const { return mpfr_zero_p(&v_->left) && mpfr_zero_p(&v_->right); }

  friend Interval operator+(const Interval& a, const Interval& b) { return apply(mpfi_add, a, b); }
  friend Interval operator-(const Interval& a, const Interval& b) { return apply(mpfi_sub, a, b); }
  friend Interval operator*(const Interval& a, const Interval& b) { return apply(mpfi_mul, a, b); }
  friend Interval operator/(const Interval& a, const Interval& b) { return apply(mpfi_div, a, b); }
  friend Interval operator-(const Interval& a) {
    Interval r;
    mpfi_neg(r.v_, a.v_);
    return r;
  }
  Interval& operator+=(const Interval& b) {
    mpfi_add(v_, v_, b.v_);
    return *this;
  }
  friend Interval operator*(long k, const Interval& a) {
    Interval r;
    mpfi_mul_si(r.v_, a.v_, k);
    return r;
  }
  friend Interval scale2(const Interval& a, long e) {  // a 2^e, exact
    Interval r;
    mpfi_mul_2si(r.v_, a.v_, e);
    return r;
  }
  friend Interval sqrt(const Interval& a) { return apply(mpfi_sqrt, a); }
  friend Interval atan(const Interval& a) { return apply(mpfi_atan, a); }
  friend Interval sin(const Interval& a) { return apply(mpfi_sin, a); }
  friend Interval cos(const Interval& a) { return apply(mpfi_cos, a); }

 private:
  template <class F>
  static Interval apply(F f, const Interval& a, const Interval& b) {
    Interval r;
    f(r.v_, a.v_, b.v_);
    return r;
  }
  template <class F>
  static Interval apply(F f, const Interval& a) {
    Interval r;
    f(r.v_, a.v_);
    return r;
  }

  mpfi_t v_;
};

// An MPFR number at a given precision (RAII), for end points.
class Real {
 public:
  explicit Real(mpfr_prec_t bits) { mpfr_init2(v_, bits); }
  ~Real() { mpfr_clear(v_); }
  Real(const Real&) = delete;
  Real& operator=(const Real&) = delete;
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }

 private:
  mpfr_t v_;
};

// The decimal digits of an MPFR number, enough to read it back (for reports of enclosures).
std::string to_decimal(mpfr_srcptr x);

}  // namespace hinge::oracle::detail
