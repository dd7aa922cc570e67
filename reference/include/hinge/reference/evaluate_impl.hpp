// hinge/reference/evaluate_impl.hpp: definitions of the templates declared in evaluate.hpp. Included by
// the explicit-instantiation units (src/instantiate_*.cpp) and by users instantiating other scalars.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "hinge/core/errors.hpp"
#include "hinge/core/fp_environment.hpp"
#include "hinge/core/hinge_checks.hpp"
#include "hinge/core/predicates.hpp"
#include "hinge/reference/evaluate.hpp"

namespace hinge::reference {

template <HingeScalar Scalar>
PreparedHinge<Scalar> prepare_hinge(const std::array<double, 12>& x) {
  check_fp_environment();  // the exact steps below need rounding to nearest and subnormals
  check_hinge(x);          // docs/contract.md: non-finite, zero-length hinge edge, zero-area triangle (exactly)
  PreparedHinge<Scalar> p;
  p.sign = static_cast<ExactSign>(
      hinge_orientation_exact({x[0], x[1], x[2]}, {x[3], x[4], x[5]}, {x[6], x[7], x[8]}, {x[9], x[10], x[11]}));
  if constexpr (std::is_floating_point_v<Scalar>) {
    // Power-of-two scaling (see evaluate.hpp). Differences are taken in long double (exact when the two
    // exponents are within 11 binades; no overflow), then scaled exactly.
    long double largest = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < a; ++b)
        for (int c = 0; c < 3; ++c)
          largest = std::max(largest, std::fabs(static_cast<long double>(x[3 * a + c]) - x[3 * b + c]));
    p.exponent = std::ilogb(largest);
    // The stencil of a built-in type is computed one format wider (float in double, double in long
    // double) and rounded once, quantity by quantity: eq. (6) adds upper- and lower-triangle terms that
    // nearly cancel on near-folded hinges, which multiplies the few-unit errors of n, m_i and h_i
    // computed in Scalar itself (measured: 17 units of 2^-53 in the double Hessian, 3.9 with the
    // stencil rounded once). See docs/numerics.md.
    using Wide = std::conditional_t<std::same_as<Scalar, float>, double, long double>;
    auto diff = [&x, e = p.exponent](int a, int b) {
      Vec3<Wide> d;
      for (int c = 0; c < 3; ++c)
        d[c] = static_cast<Wide>(std::ldexp(static_cast<long double>(x[3 * a + c]) - x[3 * b + c], -e));
      return d;
    };
    p.stencil =
        round_to<Scalar>(make_stencil(HingeEdges<Wide>{diff(2, 1), diff(0, 2), diff(1, 0), diff(3, 2), diff(1, 3)}));
  } else if constexpr (QdScalar<Scalar>) {
    // QD's types have double's exponent range: the edges are brought by a power of two to a largest
    // component in [1, 2), exactly (as for the built-in types; QD's atan2 fails on the infinities and
    // zeros that unscaled products of far-from-unit edges give). A difference that overflows is formed
    // from the quartered coordinates.
    HingeEdges<Scalar> e = hinge_edges<Scalar>(x);
    double largest = 0;
    for (const Vec3<Scalar>* v : {&e.e0, &e.e1, &e.e2, &e.et1, &e.et2})
      for (int c = 0; c < 3; ++c) largest = std::max(largest, std::fabs(to_double((*v)[c])));
    if (!(largest <= std::numeric_limits<double>::max())) {
      std::array<double, 12> quarter;
      for (int i = 0; i < 12; ++i) quarter[i] = x[i] * 0x1p-4;
      e = hinge_edges<Scalar>(quarter);
      largest = 0;
      for (const Vec3<Scalar>* v : {&e.e0, &e.e1, &e.e2, &e.et1, &e.et2})
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::fabs(to_double((*v)[c])));
      p.exponent = 4;
    }
    const int shift = std::ilogb(largest);
    for (Vec3<Scalar>* v : {&e.e0, &e.e1, &e.e2, &e.et1, &e.et2})
      for (int c = 0; c < 3; ++c) (*v)[c] = ldexp((*v)[c], -shift);
    p.exponent += shift;
    p.stencil = make_stencil(e);
  } else {
    p.stencil = make_stencil(hinge_edges<Scalar>(x));
  }
  return p;
}

template <HingeScalar Scalar>
ThetaDerivatives<Scalar> theta_derivatives(const std::array<double, 12>& x, bool with_hessian) {
  return theta_derivatives(prepare_hinge<Scalar>(x), with_hessian);
}

}  // namespace hinge::reference
