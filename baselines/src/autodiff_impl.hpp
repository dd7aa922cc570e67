// hinge::baselines::autodiff_derivatives (hinge/baselines/derivatives.hpp): Eigen's forward-mode AutoDiff on
// the atan2 definition, nested once for the Hessian. Instantiated per scalar family (autodiff_*.cpp).
#pragma once

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <limits>

#include "common.hpp"
#include "hinge/baselines/derivatives.hpp"

namespace hinge::baselines {
namespace detail {

// The value of a (nested) AutoDiffScalar: what its atan2 passes to the scalar type's.
template <class T>
auto value_of(const T& t) {
  if constexpr (HingeScalar<T>) return t;
  else return value_of(t.value());
}

// t times 2^e, value and derivatives (exact).
template <class T>
T scaled(const T& t, int e) {
  if constexpr (HingeScalar<T>) {
    return ldexp(t, e);
  } else {
    T r = t;
    r.value() = scaled(t.value(), e);
    for (Eigen::Index i = 0; i < t.derivatives().size(); ++i) r.derivatives()[i] = scaled(t.derivatives()[i], e);
    return r;
  }
}

// Thrown where atan2 is undefined in a QD type (common.hpp): the results are NaN.
struct NotANumber {};

// theta of the hinge p (x0.x, ..., x3.z) in any T: the atan2 definition of docs/contract.md, as written.
// (Dot and cross products spelled out: Eigen's reductions construct T from an int, which the nested
// AutoDiffScalar of QD's types cannot take.)
template <class T>
T theta_of(const std::array<T, 12>& p) {
  using V = std::array<T, 3>;
  auto sub = [&](int i, int j) {
    return V{p[3 * i] - p[3 * j], p[3 * i + 1] - p[3 * j + 1], p[3 * i + 2] - p[3 * j + 2]};
  };
  auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot = [](const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const V e0 = sub(2, 1);
  const V N = cross(sub(1, 0), sub(2, 0));
  const V Nt = cross(sub(2, 3), sub(1, 3));
  using std::atan2;
  using std::sqrt;
  const T y = dot(cross(N, Nt), e0) / sqrt(dot(e0, e0)), x = dot(N, Nt);
  if constexpr (QdScalar<decltype(value_of(y))>) {  // QD's atan2 needs its arguments near 1 (common.hpp)
    const std::optional<int> e = qd_atan2_exponent(value_of(y), value_of(x));
    if (!e) throw NotANumber{};
    return atan2(scaled(y, -*e), scaled(x, -*e));
  }
  return atan2(y, x);
}

}  // namespace detail

template <HingeScalar Scalar>
Derivatives<Scalar> autodiff_derivatives(const std::array<double, 12>& x, Outputs outputs) {
  const std::array<Scalar, 12> s = detail::checked_coordinates<Scalar>(x);
  Derivatives<Scalar> d = detail::zero_derivatives<Scalar>();
  using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<Scalar, 12, 1>>;
  try {
    switch (outputs) {
      case Outputs::theta: d.theta = detail::theta_of(s); break;
      case Outputs::gradient: {
        std::array<Inner, 12> p;
        for (int i = 0; i < 12; ++i) p[i] = Inner(s[i], 12, i);  // value s[i], derivative the i-th unit vector
        const Inner t = detail::theta_of(p);
        d.theta = t.value();
        d.grad = t.derivatives();
        break;
      }
      case Outputs::hessian: {
        using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, 12, 1>>;
        std::array<Outer, 12> p;
        for (int i = 0; i < 12; ++i) {
          p[i].value() = Inner(s[i], 12, i);
          p[i].derivatives() = Eigen::Matrix<Inner, 12, 1>::Unit(12, i);
          for (int j = 0; j < 12; ++j) p[i].derivatives()[j].derivatives().setZero();
        }
        const Outer t = detail::theta_of(p);
        d.theta = t.value().value();
        d.grad = t.value().derivatives();
        for (int i = 0; i < 12; ++i) d.hess.row(i) = t.derivatives()[i].derivatives().transpose();
        break;
      }
    }
  } catch (const detail::NotANumber&) {
    const Scalar nan(std::numeric_limits<double>::quiet_NaN());
    d.theta = nan;
    d.grad.setConstant(nan);
    if (outputs == Outputs::hessian) d.hess.setConstant(nan);
    return d;
  }
  d.theta = detail::on_branch(d.theta);
  return d;
}

}  // namespace hinge::baselines

#define HINGE_AUTODIFF_INSTANTIATE(S)                                                                                \
  template hinge::baselines::Derivatives<S> hinge::baselines::autodiff_derivatives<S>(const std::array<double, 12>&, \
                                                                                      Outputs);
