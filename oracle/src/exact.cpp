// The exact stage of the certified oracle (hinge/oracle/exact.hpp): integer edge vectors and normals,
// the checks, and eqs. (4)-(6) over a common denominator (exact_form.hpp, written once for the integers
// here and for the fast path's bounded double-double).
#include "hinge/oracle/exact.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "exact_form.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/core/hinge_checks.hpp"

namespace hinge::oracle {
namespace {

using V3 = detail::V3<Int>;

V3 vertex(const ScaledHinge& x, int v) { return {x.X[3 * v], x.X[3 * v + 1], x.X[3 * v + 2]}; }

}  // namespace

ScaledHinge scale_exactly(const std::array<double, 12>& x) {
  // x = m 2^e with an integer |m| < 2^53; then X = m 2^(e - e_min), F = -e_min.
  std::array<long, 12> mantissa{}, exponent{};
  long e_min = LONG_MAX;
  for (int i = 0; i < 12; ++i) {
    if (!std::isfinite(x[i])) check_finite(x);  // throws, naming the first non-finite coordinate
    if (x[i] == 0) continue;
    int e = 0;
    const double f = std::frexp(x[i], &e);  // x = f 2^e, 0.5 <= |f| < 1
    mantissa[i] = static_cast<long>(std::ldexp(f, 53));
    exponent[i] = e - 53;
    e_min = std::min(e_min, exponent[i]);
  }
  if (e_min == LONG_MAX) e_min = 0;
  ScaledHinge h;
  h.F = -e_min;
  for (int i = 0; i < 12; ++i) {
    h.X[i] = mantissa[i];
    if (mantissa[i] != 0) h.X[i] <<= static_cast<mp_bitcnt_t>(exponent[i] - e_min);
  }
  return h;
}

ScaledHinge refine(const ScaledHinge& h, unsigned long extra) {
  ScaledHinge r = h;
  for (auto& v : r.X) v <<= extra;
  r.F += static_cast<long>(extra);
  return r;
}

std::size_t ExactHinge::max_bits() const {
  std::size_t bits = 0;
  auto see = [&bits](const Int& v) { bits = std::max(bits, mpz_sizeinbase(v.get_mpz_t(), 2)); };
  for (const Int* v : {&s, &nn, &tt, &X, &Y, &g_den, &h_den}) see(*v);
  for (const auto& v : g) see(v);
  if (has_hessian)
    for (const auto& v : h) see(v);
  return bits;
}

ExactHinge exact_hinge(const std::array<double, 12>& x, bool with_hessian) {
  return exact_hinge(scale_exactly(x), with_hessian);
}

ExactHinge exact_hinge(const ScaledHinge& x, bool with_hessian) {
  const V3 x0 = vertex(x, 0), x1 = vertex(x, 1), x2 = vertex(x, 2), x3 = vertex(x, 3);
  detail::Edges<Int> e;
  for (int c = 0; c < 3; ++c) {  // Fig. 1
    e.e0[c] = x2[c] - x1[c];
    e.e1[c] = x0[c] - x2[c];
    e.e2[c] = x1[c] - x0[c];
    e.et1[c] = x3[c] - x2[c];
    e.et2[c] = x1[c] - x3[c];
  }
  if (sgn(e.e0[0]) == 0 && sgn(e.e0[1]) == 0 && sgn(e.e0[2]) == 0) throw_zero_hinge_edge();
  const V3 N = detail::upper_normal(e), Nt = detail::lower_normal(e);
  detail::Form<Int> f;
  f.nn = detail::form::dot(N, N);
  f.tt = detail::form::dot(Nt, Nt);
  if (sgn(f.nn) == 0) throw_zero_area(true);
  if (sgn(f.tt) == 0) throw_zero_area(false);
  detail::fill_form(e, N, Nt, f, with_hessian);
  ExactHinge r;
  r.F = x.F;
  r.s = std::move(f.s);
  r.nn = std::move(f.nn);
  r.tt = std::move(f.tt);
  r.X = std::move(f.X);
  r.Y = std::move(f.Y);
  r.g = std::move(f.g);
  r.g_den = std::move(f.g_den);
  r.has_hessian = with_hessian;
  if (with_hessian) {
    r.h = std::move(f.h);
    r.h_den = std::move(f.h_den);
  }
  return r;
}

bool same_angle(const ExactHinge& a, const ExactHinge& b) {
  if (sgn(a.Y) != sgn(b.Y) || sgn(a.X) != sgn(b.X)) return false;
  return a.X * a.X * b.nn * b.tt == b.X * b.X * a.nn * a.tt;
}

}  // namespace hinge::oracle
