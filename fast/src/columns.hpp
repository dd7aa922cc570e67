// fast/src/columns.hpp: a 3-vector held in the lanes of one register, the unit in which the kernels
// build their 3 x 3 blocks (one column at a time). For double it is a GCC vector of four doubles (lane 3
// unused): every operation is elementwise IEEE arithmetic, so the results are those of the scalar code,
// bit for bit, on any instruction set; for the other scalar types it is a plain struct of three.
#pragma once

#include <array>

#include "exact.hpp"

#if defined(__GNUC__) && !defined(__clang__)
// The vectors never cross a non-inlined call: the ABI note about passing them without AVX is moot.
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace hinge::fast {

template <class Scalar>
struct Triple {
  Scalar v[3];
  HINGE_FAST_INLINE Scalar& operator[](int i) { return v[i]; }
  HINGE_FAST_INLINE const Scalar& operator[](int i) const { return v[i]; }
  friend HINGE_FAST_INLINE Triple operator+(const Triple& a, const Triple& b) {
    return {{a[0] + b[0], a[1] + b[1], a[2] + b[2]}};
  }
  friend HINGE_FAST_INLINE Triple operator-(const Triple& a, const Triple& b) {
    return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}};
  }
  friend HINGE_FAST_INLINE Triple operator-(const Triple& a) { return {{-a[0], -a[1], -a[2]}}; }
  friend HINGE_FAST_INLINE Triple operator*(const Triple& a, const Scalar& s) {
    return {{a[0] * s, a[1] * s, a[2] * s}};
  }
  friend HINGE_FAST_INLINE Triple operator*(const Scalar& s, const Triple& a) {
    return {{s * a[0], s * a[1], s * a[2]}};
  }
  friend HINGE_FAST_INLINE Triple operator/(const Triple& a, const Scalar& s) {
    return {{a[0] / s, a[1] / s, a[2] / s}};
  }
  HINGE_FAST_INLINE Triple& operator+=(const Triple& b) {
    v[0] += b[0];
    v[1] += b[1];
    v[2] += b[2];
    return *this;
  }
};

template <class Scalar>
struct ColumnOf {
  using type = Triple<Scalar>;
};
#if defined(__GNUC__) && !defined(__clang__)
template <>
struct ColumnOf<double> {
  typedef double type __attribute__((vector_size(32)));
};
#endif
template <class Scalar>
using Column = typename ColumnOf<Scalar>::type;

template <class Scalar>
HINGE_FAST_INLINE Column<Scalar> column(const Scalar& a, const Scalar& b, const Scalar& c) {
  if constexpr (std::is_same_v<Column<Scalar>, Triple<Scalar>>) return Column<Scalar>{{a, b, c}};
  else return Column<Scalar>{a, b, c, Scalar(0)};
}
template <class Scalar>
HINGE_FAST_INLINE Column<Scalar> column(const std::array<Scalar, 3>& a) {
  return column<Scalar>(a[0], a[1], a[2]);
}
template <class Scalar>
HINGE_FAST_INLINE void store(Scalar* p, const Column<Scalar>& v) {
  p[0] = v[0];
  p[1] = v[1];
  p[2] = v[2];
}

}  // namespace hinge::fast
