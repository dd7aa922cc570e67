// The projected Hessian at 256 bits (hinge/oracle/projected.hpp).
#include "hinge/oracle/projected.hpp"

#include <mpfr.h>

#include "hinge/core/errors.hpp"
#include "hinge/oracle/exact.hpp"
#include "hinge_energy.hpp"
#include "interval.hpp"

namespace hinge::oracle {
namespace {

constexpr mpfr_prec_t bits = 320;  // 64 guard bits over the 256 of the result's claim

// A 12 x 12 matrix of MPFR numbers (RAII).
class Matrix {
 public:
  Matrix() {
    for (auto& row : a_)
      for (auto& v : row) mpfr_init2(v, bits), mpfr_set_ui(v, 0, MPFR_RNDN);
  }
  ~Matrix() {
    for (auto& row : a_)
      for (auto& v : row) mpfr_clear(v);
  }
  Matrix(const Matrix&) = delete;
  Matrix& operator=(const Matrix&) = delete;
  mpfr_ptr operator()(int i, int j) { return a_[i][j]; }

 private:
  mpfr_t a_[12][12];
};

// One scratch number (RAII).
struct Scratch {
  Scratch() { mpfr_init2(v, bits); }
  ~Scratch() { mpfr_clear(v); }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  mpfr_t v;
};

// A <- J^T A J and V <- V J for the Jacobi rotation J(p, q) that zeroes A(p, q) (Rutishauser's formulas).
void rotate(Matrix& A, Matrix& V, int p, int q) {
  Scratch theta, t, c, s, tmp, x, y;
  // theta = (a_qq - a_pp) / (2 a_pq); t = sign(theta) / (|theta| + sqrt(theta^2 + 1)); c = 1 / sqrt(t^2 + 1); s = t c
  mpfr_sub(theta.v, A(q, q), A(p, p), MPFR_RNDN);
  mpfr_div(theta.v, theta.v, A(p, q), MPFR_RNDN);
  mpfr_div_2ui(theta.v, theta.v, 1, MPFR_RNDN);
  mpfr_sqr(tmp.v, theta.v, MPFR_RNDN);
  mpfr_add_ui(tmp.v, tmp.v, 1, MPFR_RNDN);
  mpfr_sqrt(tmp.v, tmp.v, MPFR_RNDN);
  mpfr_abs(t.v, theta.v, MPFR_RNDN);
  mpfr_add(tmp.v, tmp.v, t.v, MPFR_RNDN);
  mpfr_ui_div(t.v, 1, tmp.v, MPFR_RNDN);
  if (mpfr_sgn(theta.v) < 0) mpfr_neg(t.v, t.v, MPFR_RNDN);
  mpfr_sqr(tmp.v, t.v, MPFR_RNDN);
  mpfr_add_ui(tmp.v, tmp.v, 1, MPFR_RNDN);
  mpfr_rec_sqrt(c.v, tmp.v, MPFR_RNDN);
  mpfr_mul(s.v, t.v, c.v, MPFR_RNDN);
  // a_pp -= t a_pq, a_qq += t a_pq, a_pq = 0
  mpfr_mul(tmp.v, t.v, A(p, q), MPFR_RNDN);
  mpfr_sub(A(p, p), A(p, p), tmp.v, MPFR_RNDN);
  mpfr_add(A(q, q), A(q, q), tmp.v, MPFR_RNDN);
  mpfr_set_ui(A(p, q), 0, MPFR_RNDN);
  mpfr_set_ui(A(q, p), 0, MPFR_RNDN);
  for (int r = 0; r < 12; ++r) {
    if (r != p && r != q) {  // a_rp = c a_rp - s a_rq, a_rq = s a_rp + c a_rq (and symmetric)
      mpfr_mul(x.v, c.v, A(r, p), MPFR_RNDN);
      mpfr_mul(tmp.v, s.v, A(r, q), MPFR_RNDN);
      mpfr_sub(x.v, x.v, tmp.v, MPFR_RNDN);
      mpfr_mul(y.v, s.v, A(r, p), MPFR_RNDN);
      mpfr_mul(tmp.v, c.v, A(r, q), MPFR_RNDN);
      mpfr_add(y.v, y.v, tmp.v, MPFR_RNDN);
      mpfr_set(A(r, p), x.v, MPFR_RNDN);
      mpfr_set(A(p, r), x.v, MPFR_RNDN);
      mpfr_set(A(r, q), y.v, MPFR_RNDN);
      mpfr_set(A(q, r), y.v, MPFR_RNDN);
    }
    mpfr_mul(x.v, c.v, V(r, p), MPFR_RNDN);  // the eigenvectors, columns of V
    mpfr_mul(tmp.v, s.v, V(r, q), MPFR_RNDN);
    mpfr_sub(x.v, x.v, tmp.v, MPFR_RNDN);
    mpfr_mul(y.v, s.v, V(r, p), MPFR_RNDN);
    mpfr_mul(tmp.v, c.v, V(r, q), MPFR_RNDN);
    mpfr_add(y.v, y.v, tmp.v, MPFR_RNDN);
    mpfr_set(V(r, p), x.v, MPFR_RNDN);
    mpfr_set(V(r, q), y.v, MPFR_RNDN);
  }
}

}  // namespace

std::array<double, 144> projected_hessian_256(const std::array<double, 12>& x, const std::array<double, 12>& rest,
                                              const EnergyParameters& parameters) {
  const ExactHinge deformed = exact_hinge(x, true), r = exact_hinge(rest, false);
  if (infinite_at_pi(parameters.model) && sgn(r.Y) == 0 && sgn(r.X) < 0) throw_folded_rest(parameters.model);
  detail::WorkingPrecision precision(bits);
  const detail::HingeEnergy h =
      detail::hinge_energy(parameters.model, detail::Interval(parameters.k), detail::Interval(parameters.k_d_over_dt),
                           deformed, r, same_angle(deformed, r), true, true, false);
  Matrix A, V;
  for (int i = 0; i < 12; ++i) {
    mpfr_set_ui(V(i, i), 1, MPFR_RNDN);
    for (int j = 0; j < 12; ++j) mpfi_mid(A(i, j), h.hess[12 * i + j].get());
  }
  for (int i = 0; i < 12; ++i)  // symmetric exactly: the mean of the two midpoints
    for (int j = i + 1; j < 12; ++j) {
      mpfr_add(A(i, j), A(i, j), A(j, i), MPFR_RNDN);
      mpfr_div_2ui(A(i, j), A(i, j), 1, MPFR_RNDN);
      mpfr_set(A(j, i), A(i, j), MPFR_RNDN);
    }
  Scratch norm, off, tmp;
  mpfr_set_ui(norm.v, 0, MPFR_RNDN);
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      mpfr_sqr(tmp.v, A(i, j), MPFR_RNDN);
      mpfr_add(norm.v, norm.v, tmp.v, MPFR_RNDN);
    }
  mpfr_mul_2si(norm.v, norm.v, -512, MPFR_RNDN);  // (2^-256 ||H||_F)^2
  for (int sweep = 0; sweep < 64; ++sweep) {
    mpfr_set_ui(off.v, 0, MPFR_RNDN);
    for (int i = 0; i < 12; ++i)
      for (int j = i + 1; j < 12; ++j) {
        mpfr_sqr(tmp.v, A(i, j), MPFR_RNDN);
        mpfr_add(off.v, off.v, tmp.v, MPFR_RNDN);
      }
    if (mpfr_lessequal_p(off.v, norm.v)) break;
    for (int p = 0; p < 12; ++p)
      for (int q = p + 1; q < 12; ++q)
        if (!mpfr_zero_p(A(p, q))) rotate(A, V, p, q);
  }
  std::array<double, 144> out{};
  Scratch sum;
  for (int i = 0; i < 12; ++i)
    for (int j = i; j < 12; ++j) {
      mpfr_set_ui(sum.v, 0, MPFR_RNDN);
      for (int k = 0; k < 12; ++k) {
        if (mpfr_sgn(A(k, k)) <= 0) continue;  // max(lambda_k, 0)
        mpfr_mul(tmp.v, V(i, k), V(j, k), MPFR_RNDN);
        mpfr_mul(tmp.v, tmp.v, A(k, k), MPFR_RNDN);
        mpfr_add(sum.v, sum.v, tmp.v, MPFR_RNDN);
      }
      out[12 * i + j] = out[12 * j + i] = mpfr_get_d(sum.v, MPFR_RNDN);
    }
  return out;
}

}  // namespace hinge::oracle
