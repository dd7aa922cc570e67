// tests/support/generators.hpp: RapidCheck generators for the property suite (tests/properties,
// docs/testing.md): hinges aimed at the hard cases, exact rigid motions and general ones, relabellings,
// meshes with random rest states, and inputs that must be rejected. Every generator draws integers and
// maps them (so that RapidCheck shrinks towards simple shapes: the drawn integers shrink towards their
// lower bounds), and every value shows itself exactly (17 significant digits) in a failure report.
//
// The hinge stencil (docs/contract.md): x1 -> x2 is the hinge edge, T = (x0, x1, x2), T~ = (x3, x2, x1).
// Generated in a local frame, then rotated, scaled and moved:
//
//          x0 = (a, b, 0)                     x1 = (0, 0, 0),  x2 = (l0, 0, 0)
//           /  \                              x3 = (c, -d cos(theta), -d sin(theta))
//         x1 -- x2   (the x axis)             so that the bend angle is theta (n = +z, n~ = R_x(theta) z:
//           \  /                              (n x n~) . e0 = sin(theta))
//            x3
//
// Variables: x0, x1, x2, x3 (12), x0.x first.
#pragma once

#include <rapidcheck.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <numeric>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "hinge/core/mesh.hpp"
#include "hinge/core/predicates.hpp"
#include "hinge/reference/evaluate.hpp"
#include "support/tolerance.hpp"

namespace hinge::test {

using Coordinates = std::array<double, 12>;
using Matrix3l = Eigen::Matrix<long double, 3, 3>;
using Vector3l = Eigen::Matrix<long double, 3, 1>;

// ---------------------------------------------------------------------------------------------------
// Depth: HINGE_TEST_DEPTH=quick (default, CI) or deep. RapidCheck reads its parameters from RC_PARAMS
// once, on the first property; set_depth_from_environment() (called before that, by a static object in
// the suite) adds max_success=100 (quick) or 10000 (deep) unless RC_PARAMS already names max_success.
// A failure prints RapidCheck's seed and a `reproduce=` string for RC_PARAMS that replays it.
// ---------------------------------------------------------------------------------------------------
inline int depth_max_success() {
  const char* depth = std::getenv("HINGE_TEST_DEPTH");
  return (depth && std::string(depth) == "deep") ? 10000 : 100;
}
inline void set_depth_from_environment() {
  const char* params = std::getenv("RC_PARAMS");
  std::string value = params ? params : "";
  if (value.find("max_success") != std::string::npos) return;
  value += (value.empty() ? "" : " ") + std::string("max_success=") + std::to_string(depth_max_success());
  setenv("RC_PARAMS", value.c_str(), 1);
}

// ---------------------------------------------------------------------------------------------------
// Numbers. Drawn as integers so that shrinking is meaningful; every map is monotone.
// ---------------------------------------------------------------------------------------------------
namespace gen {

// Uniform in [lo, hi) on a grid of 2^-53 (hi - lo); shrinks towards lo.
inline rc::Gen<double> uniform(double lo, double hi) {
  return rc::gen::map(rc::gen::inRange<std::int64_t>(0, std::int64_t(1) << 53), [lo, hi](std::int64_t k) {
    return static_cast<double>(static_cast<long double>(lo) +
                               static_cast<long double>(hi - lo) * (static_cast<long double>(k) * 0x1p-53L));
  });
}

// 10^U(lo, hi): log-uniform over decades; shrinks towards 10^lo.
inline rc::Gen<long double> decades(double lo, double hi) {
  return rc::gen::map(uniform(lo, hi), [](double e) { return std::pow(10.0L, static_cast<long double>(e)); });
}

inline rc::Gen<int> sign() { return rc::gen::element(1, -1); }

}  // namespace gen

// ---------------------------------------------------------------------------------------------------
// Rigid motions and reflections: a 3x3 matrix, exact (signed permutations) or rounded (general).
// ---------------------------------------------------------------------------------------------------
struct Motion {
  std::string kind;  // "pi about x", "permutation (1 2 0)", "reflection x", "rotation", "reflection"
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  bool exact = false;  // a signed permutation: applying it to doubles is exact
  int det = 1;         // +1 rotation, -1 reflection
};

inline void showValue(const Motion& m, std::ostream& os) {
  os << m.kind << " R = " << show_exactly_all(m.R) << " (det " << m.det << ")";
}

// y = R x for every vertex. Exact for signed permutations; otherwise each coordinate is R x in long double
// rounded once to double (the exact input of the moved hinge is that rounded value).
inline Coordinates apply_motion(const Motion& m, const Coordinates& x) {
  Coordinates y;
  for (int v = 0; v < 4; ++v)
    for (int r = 0; r < 3; ++r) {
      long double s = 0;
      for (int c = 0; c < 3; ++c) s += static_cast<long double>(m.R(r, c)) * x[3 * v + c];
      y[3 * v + r] = static_cast<double>(s);
    }
  return y;
}

// The 12 x 12 block-diagonal matrix diag(R, R, R, R): grad -> R grad, Hess -> R Hess R^T.
inline Eigen::Matrix<double, 12, 12> block_diagonal(const Eigen::Matrix3d& R) {
  Eigen::Matrix<double, 12, 12> B = Eigen::Matrix<double, 12, 12>::Zero();
  for (int v = 0; v < 4; ++v) B.block<3, 3>(3 * v, 3 * v) = R;
  return B;
}

namespace gen {

// Rotation by pi about a coordinate axis: two coordinates negated (exact).
inline rc::Gen<Motion> pi_rotation() {
  return rc::gen::map(rc::gen::inRange(0, 3), [](int axis) {
    Motion m;
    m.kind = std::string("pi about ") + "xyz"[axis];
    for (int c = 0; c < 3; ++c) m.R(c, c) = c == axis ? 1 : -1;
    m.exact = true;
    return m;
  });
}

// Reflection in a coordinate plane: one coordinate negated (exact).
inline rc::Gen<Motion> coordinate_reflection() {
  return rc::gen::map(rc::gen::inRange(0, 3), [](int axis) {
    Motion m;
    m.kind = std::string("reflection ") + "xyz"[axis] + " -> -" + "xyz"[axis];
    m.R(axis, axis) = -1;
    m.exact = true;
    m.det = -1;
    return m;
  });
}

// A permutation of the axes (all six: the odd ones are reflections), exact.
inline rc::Gen<Motion> axis_permutation() {
  return rc::gen::map(rc::gen::inRange(0, 6), [](int k) {
    std::array<int, 3> p{0, 1, 2};
    for (int i = 0; i < k; ++i) std::next_permutation(p.begin(), p.end());
    Motion m;
    m.R.setZero();
    for (int r = 0; r < 3; ++r) m.R(r, p[r]) = 1;
    m.exact = true;
    m.det = m.R.determinant() > 0 ? 1 : -1;
    m.kind = "permutation (" + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + ")";
    return m;
  });
}

// A general rotation (a unit quaternion from four uniform numbers, in long double, rounded to double), or
// with `reflections` also a general reflection: that rotation times diag(1, 1, -1) (its third column
// negated), a random improper orthogonal matrix.
inline rc::Gen<Motion> general_motion(bool reflections = false) {
  return rc::gen::exec([reflections] {
    std::array<long double, 4> q;
    long double norm = 0;
    do {
      norm = 0;
      for (auto& c : q) {
        c = *uniform(-1, 1);
        norm += c * c;
      }
    } while (norm < 1e-3L);
    for (auto& c : q) c /= std::sqrt(norm);
    const long double w = q[0], i = q[1], j = q[2], k = q[3];
    Matrix3l R;
    R << 1 - 2 * (j * j + k * k), 2 * (i * j - w * k), 2 * (i * k + w * j),  //
        2 * (i * j + w * k), 1 - 2 * (i * i + k * k), 2 * (j * k - w * i),   //
        2 * (i * k - w * j), 2 * (j * k + w * i), 1 - 2 * (i * i + j * j);
    const bool reflect = reflections && *rc::gen::arbitrary<bool>();
    if (reflect) R.col(2) = -R.col(2);
    Motion m;
    m.R = R.cast<double>();
    m.kind = reflect ? "general reflection" : "general rotation";
    m.det = reflect ? -1 : 1;
    return m;
  });
}

// Any exact motion (signed permutations: pi rotations, coordinate reflections, axis permutations).
inline rc::Gen<Motion> exact_motion() {
  return rc::gen::oneOf(pi_rotation(), coordinate_reflection(), axis_permutation());
}

// Any of the above.
inline rc::Gen<Motion> any_motion() {
  return rc::gen::oneOf(pi_rotation(), coordinate_reflection(), axis_permutation(), general_motion(true));
}

}  // namespace gen

// ---------------------------------------------------------------------------------------------------
// Hinges.
// ---------------------------------------------------------------------------------------------------

// A generated hinge: the exact input `x`, the family it was aimed at, and how it was built.
struct HingeCase {
  std::string family;
  std::string recipe;  // the local shape, motion, scale and offset (for the report only)
  Coordinates x{};
};

inline void showValue(const HingeCase& h, std::ostream& os) {
  os << h.family << " hinge, " << describe(h.x) << ", kappa = " << condition_number(h.x) << " (kappa_shape "
     << shape_condition_number(h.x) << ", kappa_angle " << angle_condition_number(h.x) << "; " << h.recipe << ")";
}

// Range of the binary exponent of the hinge's size (its scale s = 2^k times a factor in [1, 2)).
struct ScaleRange {
  int lo = -40, hi = 20;  // 2^-40 ~ 1e-12 .. 2^20 ~ 1e6: the range for double
};
// The widest scales for which the exact theta derivatives of every generated hinge are normal doubles:
// |grad| ~ kappa_shape / s, |Hess| ~ kappa_shape^2 / s^2 with kappa_shape <= 1e13 (the hard families'
// limit) stay within
// 2^-1000 .. 2^1000 for s in 2^-300 .. 2^300 (1e-90 .. 1e90). Results are compared in double, so this is
// also the range for bin128 (whose own exponent range is far wider, but whose inputs are doubles).
inline constexpr ScaleRange wide_scales{-300, 300};

// The local shape of a hinge (see the sketch at the top), in long double.
struct LocalShape {
  long double l0 = 1;                        // hinge edge length
  long double a = 0.5, b = 1;                // upper apex x0 = (a, b, 0), b > 0
  long double c = 0.5, d = 1;                // lower apex at distance d from the hinge line, foot at (c, 0, 0)
  long double cos_theta = 1, sin_theta = 0;  // the bend angle, as its cosine and sine (exact near pi)
  std::string angle;                         // how theta was chosen, for the report
};

// Places a local shape: x = offset + s R p, each coordinate computed in long double and rounded once.
inline Coordinates place(const LocalShape& shape, const Matrix3l& R, long double s, const Vector3l& offset) {
  const std::array<Vector3l, 4> p{Vector3l(shape.a, shape.b, 0), Vector3l(0, 0, 0), Vector3l(shape.l0, 0, 0),
                                  Vector3l(shape.c, -shape.d * shape.cos_theta, -shape.d * shape.sin_theta)};
  Coordinates x;
  for (int v = 0; v < 4; ++v) {
    const Vector3l y = offset + s * (R * p[v]);
    for (int c = 0; c < 3; ++c) x[3 * v + c] = static_cast<double>(y[c]);
  }
  return x;
}

// The hinge is valid input: finite, x1 != x2, neither triangle of exactly zero area.
inline bool valid_hinge(const Coordinates& x) {
  for (double c : x)
    if (!std::isfinite(c)) return false;
  const Point x0{x[0], x[1], x[2]}, x1{x[3], x[4], x[5]}, x2{x[6], x[7], x[8]}, x3{x[9], x[10], x[11]};
  return x1 != x2 && !zero_area_exact(x0, x1, x2) && !zero_area_exact(x3, x2, x1);
}

namespace gen {

// A random orientation in space (quaternion), as a long double matrix.
inline rc::Gen<Matrix3l> orientation() {
  return rc::gen::map(general_motion(false), [](const Motion& m) { return Matrix3l(m.R.cast<long double>()); });
}

// theta in (-pi, pi] aimed at one of: generic (uniform), near 0 (|theta| = 10^U(-15, -1)), near +-pi
// (pi - |theta| = 10^U(-15, -1)); cosine and sine computed from the small distance itself.
inline rc::Gen<LocalShape> with_angle(const LocalShape& base_shape, int kind /* 0 generic, 1 near 0, 2 near pi */,
                                      double lo = 0.05) {
  return rc::gen::exec([base = base_shape, kind, lo] {
    LocalShape shape = base;
    const int sgn = *sign();
    if (kind == 0) {
      const long double t = *uniform(lo, 3.141592653589793 - lo);
      shape.cos_theta = std::cos(t);
      shape.sin_theta = sgn * std::sin(t);
      shape.angle = "theta = " + show_exactly(static_cast<double>(sgn * t));
    } else {
      const long double eps = *decades(-15, -1);
      shape.cos_theta = kind == 1 ? std::cos(eps) : -std::cos(eps);
      shape.sin_theta = sgn * std::sin(eps);
      shape.angle = std::string(kind == 1 ? "theta = " : "theta = pi - ") + (sgn < 0 ? "-" : "") +
                    show_exactly(static_cast<double>(eps)) + (kind == 1 ? "" : " (signed)");
    }
    return shape;
  });
}

// A hinge from a local shape: random orientation, scale 2^k m (k in range, m in [1, 2)), and an offset of
// `offset_decades` (lo, hi) times the scale in a random direction (none when hi < lo).
inline rc::Gen<HingeCase> placed(std::string family, rc::Gen<LocalShape> shapes, ScaleRange scales,
                                 std::pair<double, double> offset_decades = {0, -1}) {
  return rc::gen::exec([family, shapes, scales, offset_decades] {
    const LocalShape shape = *shapes;
    const Matrix3l R = *orientation();
    const int k = *rc::gen::inRange(scales.lo, scales.hi + 1);
    const long double s = std::ldexp(static_cast<long double>(*uniform(1, 2)), k);
    Vector3l offset(0, 0, 0);
    if (offset_decades.second >= offset_decades.first) {
      const long double distance = *decades(offset_decades.first, offset_decades.second);
      offset = s * distance * (*orientation()).col(0);
    }
    HingeCase h;
    h.family = family;
    h.x = place(shape, R, s, offset);
    std::ostringstream r;
    r.precision(17);
    r << "l0 " << static_cast<double>(shape.l0) << ", x0 (" << static_cast<double>(shape.a) << ", "
      << static_cast<double>(shape.b) << "), x3 foot " << static_cast<double>(shape.c) << " distance "
      << static_cast<double>(shape.d) << ", " << shape.angle << ", scale 2^" << k << ", offset "
      << static_cast<double>(offset.norm() / s) << " x scale";
    h.recipe = r.str();
    return h;
  });
}

// Apex positions of a hinge whose triangles have no small angle: feet in [-0.5, 1.5], heights in [0.2, 1.5].
inline rc::Gen<LocalShape> round_shape() {
  return rc::gen::exec([] {
    LocalShape s;
    s.a = *uniform(-0.5, 1.5);
    s.b = *uniform(0.2, 1.5);
    s.c = *uniform(-0.5, 1.5);
    s.d = *uniform(0.2, 1.5);
    return s;
  });
}

// Well-shaped hinges (docs/contract.md, as hinge::reference::well_shaped decides), scales in `scales`,
// offsets up to 10^3 times the size.
inline rc::Gen<HingeCase> well_shaped_hinge(ScaleRange scales = {}) {
  auto shapes = rc::gen::mapcat(round_shape(), [](LocalShape s) { return with_angle(s, 0); });
  return rc::gen::suchThat(placed("well-shaped", shapes, scales, {-1, 3}),
                           [](const HingeCase& h) { return reference::well_shaped(h.x); });
}

// The hard cases. Each family keeps the other parameters round, so that the difficulty is the named one:
//   near-flat       |theta| = 10^U(-15, -1)
//   near-folded     pi - |theta| = 10^U(-15, -1)
//   needle          an apex at height 10^U(-12, -1) over the hinge line, its foot anywhere in [-1, 2]
//                   (altitude collapse; a foot outside [0, 1] makes an obtuse needle)
//   short-edge      hinge edge of length 10^U(-12, -1) (edge collapse: h1, h2 ~ l0)
//   far             offset from the origin of 10^U(3, 8) times the size
//   combined        a needle, near flat or folded, far from the origin
// Rounding the placed coordinates may change the shape (or make it degenerate: discarded); the exact
// input is whatever doubles result, and kappa is computed from them.
inline rc::Gen<HingeCase> hard_hinge(ScaleRange scales = {}) {
  auto angle = [](int kind) { return [kind](LocalShape s) { return with_angle(s, kind); }; };
  auto needle = rc::gen::exec([] {
    LocalShape s = *round_shape();
    const long double h = *decades(-12, -1), foot = *uniform(-1, 2);
    if (*rc::gen::arbitrary<bool>()) {  // the upper triangle is the needle
      s.a = foot;
      s.b = h;
    } else {  // the lower one
      s.c = foot;
      s.d = h;
    }
    return s;
  });
  auto short_edge_shape = rc::gen::exec([] {
    LocalShape s = *round_shape();
    s.l0 = *decades(-12, -1);
    s.a *= s.l0;  // feet near the short edge; the apexes stay at heights ~1
    s.c *= s.l0;
    return s;
  });
  auto generic_angle = rc::gen::inRange(0, 3);  // generic, near 0 or near pi
  auto any_angle = [generic_angle](rc::Gen<LocalShape> shapes) {
    return rc::gen::exec([shapes, generic_angle] {
      const LocalShape s = *shapes;
      return *with_angle(s, *generic_angle);
    });
  };
  const rc::Gen<HingeCase> all = rc::gen::oneOf(
      placed("near-flat", rc::gen::mapcat(round_shape(), angle(1)), scales),
      placed("near-folded", rc::gen::mapcat(round_shape(), angle(2)), scales),
      placed("needle", any_angle(needle), scales), placed("short-edge", any_angle(short_edge_shape), scales),
      placed("far", any_angle(round_shape()), scales, {3, 8}), placed("combined", any_angle(needle), scales, {0, 6}));
  return rc::gen::suchThat(all,
                           [](const HingeCase& h) { return valid_hinge(h.x) && shape_condition_number(h.x) <= 1e13; });
}

// Either family: half well-shaped, half hard.
inline rc::Gen<HingeCase> any_hinge(ScaleRange scales = {}) {
  return rc::gen::oneOf(well_shaped_hinge(scales), hard_hinge(scales));
}

// ---------------------------------------------------------------------------------------------------
// Exact constructions: coplanar hinges (theta = 0 or +pi exactly) and invalid hinges.
// Points o + s u + t v with small integers: every coordinate is an integer below 2^20, exact, and
// then scaled by an exact power of two.
// ---------------------------------------------------------------------------------------------------

// Integer point in the plane spanned by u, v through o.
inline std::array<double, 3> plane_point(const std::array<int, 3>& o, const std::array<int, 3>& u,
                                         const std::array<int, 3>& v, int s, int t) {
  return {double(o[0] + s * u[0] + t * v[0]), double(o[1] + s * u[1] + t * v[1]), double(o[2] + s * u[2] + t * v[2])};
}

inline rc::Gen<std::array<int, 3>> small_vector(int bound) {
  return rc::gen::exec([bound] {
    return std::array<int, 3>{*rc::gen::inRange(-bound, bound + 1), *rc::gen::inRange(-bound, bound + 1),
                              *rc::gen::inRange(-bound, bound + 1)};
  });
}

// A hinge whose four points are exactly coplanar: folded flat onto itself (x0 and x3 on the same side of
// the hinge line: theta = +pi exactly) when `folded`, else flat (theta = 0 exactly).
inline rc::Gen<HingeCase> coplanar_hinge(bool folded) {
  auto g = rc::gen::exec([folded] {
    const auto o = *small_vector(1000), u = *small_vector(8), v = *small_vector(8);
    auto st = [] { return std::array<int, 2>{*rc::gen::inRange(-20, 21), *rc::gen::inRange(-20, 21)}; };
    const auto p0 = st(), p1 = st(), p2 = st(), p3 = st();
    const int k = *rc::gen::inRange(-60, 61);
    HingeCase h;
    h.family = folded ? "folded exactly" : "flat exactly";
    const std::array<std::array<int, 2>, 4> p{p0, p1, p2, p3};
    for (int i = 0; i < 4; ++i) {
      const auto q = plane_point(o, u, v, p[i][0], p[i][1]);
      for (int c = 0; c < 3; ++c) h.x[3 * i + c] = std::ldexp(q[c], k);
    }
    // The side of x0 and of x3 relative to the line x1 -> x2, in the plane's own coordinates (exact).
    auto side = [&](const std::array<int, 2>& q) {
      return (long long)(p2[0] - p1[0]) * (q[1] - p1[1]) - (long long)(p2[1] - p1[1]) * (q[0] - p1[0]);
    };
    const long long s0 = side(p0), s3 = side(p3);
    h.recipe = "plane through o along u, v; 2^" + std::to_string(k) + "; sides " + std::to_string(s0) + ", " +
               std::to_string(s3);
    // Folded: same side. Flat: opposite sides. (u, v independent and both sides nonzero: checked below.)
    const bool ok = s0 != 0 && s3 != 0 && ((s0 > 0) == (s3 > 0)) == folded;
    if (!ok) h.family = "rejected";
    return h;
  });
  return rc::gen::suchThat(g, [](const HingeCase& h) { return h.family != "rejected" && valid_hinge(h.x); });
}

// Hinges that must be rejected with hinge::InputError: a triangle of exactly zero area (three collinear
// points, exactly), coincident vertices of one triangle, a zero-length hinge edge, a non-finite coordinate.
inline rc::Gen<HingeCase> invalid_hinge() {
  return rc::gen::exec([] {
    const auto o = *small_vector(1 << 19), w = *small_vector(16), free0 = *small_vector(1 << 19);
    const int kind = *rc::gen::inRange(0, 6);
    const int k = *rc::gen::inRange(-60, 61);
    auto on_line = [&](int t) {
      return std::array<double, 3>{double(o[0] + t * w[0]), double(o[1] + t * w[1]), double(o[2] + t * w[2])};
    };
    std::array<std::array<double, 3>, 4> p;
    const int t0 = *rc::gen::inRange(-20, 21), t2 = *rc::gen::inRange(1, 21);
    p[1] = on_line(0);
    p[2] = on_line(t2);
    p[0] = {double(free0[0]), double(free0[1]), double(free0[2])};
    p[3] = {double(free0[2]), double(-free0[0]), double(free0[1] + 7)};
    HingeCase h;
    switch (kind) {
      case 0:
        h.family = "zero-area upper triangle (x0 on the hinge line)";
        p[0] = on_line(t0);
        break;
      case 1:
        h.family = "zero-area lower triangle (x3 on the hinge line)";
        p[3] = on_line(t0);
        break;
      case 2:
        h.family = "coincident x0 == x1";
        p[0] = p[1];
        break;
      case 3:
        h.family = "coincident x3 == x2";
        p[3] = p[2];
        break;
      case 4:
        h.family = "zero-length hinge edge x1 == x2";
        p[2] = p[1];
        break;
      default: h.family = "non-finite coordinate"; break;
    }
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) h.x[3 * i + c] = std::ldexp(p[i][c], k);
    if (kind == 5) h.x[*rc::gen::inRange(0, 12)] = *rc::gen::element(double(INFINITY), double(-INFINITY), double(NAN));
    h.recipe = "line through o along w, 2^" + std::to_string(k);
    return h;
  });
}

}  // namespace gen

// ---------------------------------------------------------------------------------------------------
// Relabellings of one hinge.
// ---------------------------------------------------------------------------------------------------

// The vertex order (x3, x2, x1, x0): the same hinge (upper and lower triangles exchange roles, the hinge
// edge reverses): theta is unchanged and the derivatives are permuted (docs/contract.md; docs/testing.md).
inline Coordinates relabel_hinge(const Coordinates& x) {
  Coordinates y;
  for (int v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) y[3 * v + c] = x[3 * (3 - v) + c];
  return y;
}
// The vertex order (x0, x2, x1, x3): both triangles reversed (the hinge of the mesh with every face
// reversed): theta and its derivatives change sign (docs/testing.md).
inline Coordinates reverse_hinge(const Coordinates& x) {
  Coordinates y = x;
  for (int c = 0; c < 3; ++c) std::swap(y[3 + c], y[6 + c]);
  return y;
}
// The 12 x 12 permutation matrix P with (P g) = g of the relabelled hinge, for vertex map new v <- old map[v].
inline Eigen::Matrix<double, 12, 12> vertex_permutation(const std::array<int, 4>& map) {
  Eigen::Matrix<double, 12, 12> P = Eigen::Matrix<double, 12, 12>::Zero();
  for (int v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) P(3 * v + c, 3 * map[v] + c) = 1;
  return P;
}

// ---------------------------------------------------------------------------------------------------
// Meshes: perturbed grids (both diagonal patterns, alternating, and random diagonals: irregular valences),
// open with boundaries or closed (a torus from a periodic grid; a subdivided octahedron on a sphere),
// each with a random rest state (an independent perturbation of the same faces).
// ---------------------------------------------------------------------------------------------------
struct MeshCase {
  std::string family;
  Mesh deformed, rest;
};

inline void show_mesh(const Mesh& m, std::ostream& os) {
  os.precision(17);
  for (const auto& v : m.vertices) os << "v " << v[0] << " " << v[1] << " " << v[2] << "\n";
  for (const auto& f : m.faces) os << "f " << f[0] + 1 << " " << f[1] + 1 << " " << f[2] + 1 << "\n";
}
inline void showValue(const MeshCase& m, std::ostream& os) {
  os << m.family << " mesh, " << m.deformed.vertices.size() << " vertices, " << m.deformed.faces.size()
     << " faces; deformed (OBJ):\n";
  show_mesh(m.deformed, os);
  os << "rest (OBJ):\n";
  show_mesh(m.rest, os);
}

// Faces of an nx x ny grid of quads, counter-clockwise about +z. `diagonal[q]` for quad q: 0 is '/' (from
// (i, j) to (i+1, j+1)), 1 is '\'. Periodic directions wrap around (nx, ny >= 3 there).
inline std::vector<std::array<Index, 3>> grid_faces(int nx, int ny, bool periodic_x, bool periodic_y,
                                                    const std::vector<int>& diagonal) {
  const int columns = periodic_x ? nx : nx + 1;
  auto vertex = [&](int i, int j) {
    if (periodic_x) i %= nx;
    if (periodic_y) j %= ny;
    return static_cast<Index>(i + columns * j);
  };
  std::vector<std::array<Index, 3>> faces;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Index a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
      if (diagonal[static_cast<std::size_t>(i + nx * j)] == 0) {
        faces.push_back({a, b, c});
        faces.push_back({a, c, d});
      } else {
        faces.push_back({a, b, d});
        faces.push_back({b, c, d});
      }
    }
  return faces;
}

namespace gen {

// Diagonal pattern of nq quads: all '/', all '\', alternating (checkerboard), or random (irregular).
inline rc::Gen<std::pair<std::string, std::vector<int>>> diagonals(int nx, int ny) {
  return rc::gen::exec([nx, ny] {
    const int pattern = *rc::gen::inRange(0, 4);
    std::vector<int> d(static_cast<std::size_t>(nx * ny));
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        int& v = d[static_cast<std::size_t>(i + nx * j)];
        if (pattern == 0) v = 0;
        else if (pattern == 1) v = 1;
        else if (pattern == 2) v = (i + j) % 2;
        else v = *rc::gen::inRange(0, 2);
      }
    static const char* const names[] = {"diagonals /", "diagonals \\", "alternating diagonals", "random diagonals"};
    return std::make_pair(std::string(names[pattern]), d);
  });
}

// Open perturbed grid: vertex (i, j) at (i + U(-0.25, 0.25), j + U(-0.25, 0.25), U(-0.5, 0.5)). The
// in-plane jitter keeps every triangle's projection positively oriented (no zero area), the heights keep
// |theta| well below pi.
inline rc::Gen<std::vector<std::array<double, 3>>> grid_positions(int nx, int ny) {
  return rc::gen::exec([nx, ny] {
    std::vector<std::array<double, 3>> v;
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        v.push_back({i + *uniform(-0.25, 0.25), j + *uniform(-0.25, 0.25), *uniform(-0.5, 0.5)});
    return v;
  });
}

// Torus from an nx x ny periodic grid, radii 2 and 1 (the coarsest, 3 x 3, has |theta| up to ~2.1), each
// vertex moved radially by U(-0.1, 0.1) of the tube radius.
inline rc::Gen<std::vector<std::array<double, 3>>> torus_positions(int nx, int ny) {
  return rc::gen::exec([nx, ny] {
    std::vector<std::array<double, 3>> v;
    const long double pi = 3.14159265358979323846264338327950288L;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const long double u = 2 * pi * i / nx, w = 2 * pi * j / ny, r = 1 + *uniform(-0.1, 0.1);
        v.push_back({static_cast<double>((2 + r * std::cos(w)) * std::cos(u)),
                     static_cast<double>((2 + r * std::cos(w)) * std::sin(u)), static_cast<double>(r * std::sin(w))});
      }
    return v;
  });
}

inline rc::Gen<MeshCase> grid_mesh() {
  return rc::gen::exec([] {
    const int nx = *rc::gen::inRange(1, 5), ny = *rc::gen::inRange(1, 5);
    const auto [pattern, d] = *diagonals(nx, ny);
    MeshCase m;
    m.family = "open grid " + std::to_string(nx) + "x" + std::to_string(ny) + ", " + pattern;
    m.deformed.faces = m.rest.faces = grid_faces(nx, ny, false, false, d);
    m.deformed.vertices = *grid_positions(nx, ny);
    m.rest.vertices = *grid_positions(nx, ny);
    return m;
  });
}

inline rc::Gen<MeshCase> torus_mesh() {
  return rc::gen::exec([] {
    const int nx = *rc::gen::inRange(3, 6), ny = *rc::gen::inRange(3, 6);
    const auto [pattern, d] = *diagonals(nx, ny);
    MeshCase m;
    m.family = "closed torus " + std::to_string(nx) + "x" + std::to_string(ny) + ", " + pattern;
    m.deformed.faces = m.rest.faces = grid_faces(nx, ny, true, true, d);
    m.deformed.vertices = *torus_positions(nx, ny);
    m.rest.vertices = *torus_positions(nx, ny);
    return m;
  });
}

// Octahedron, optionally subdivided once (each face into four; vertex valences 4 and 6), on the unit
// sphere with radial jitter U(-0.1, 0.1).
inline rc::Gen<MeshCase> sphere_mesh() {
  return rc::gen::exec([] {
    std::vector<Vector3l> p{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::vector<std::array<Index, 3>> f{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    const bool subdivide = *rc::gen::arbitrary<bool>();
    if (subdivide) {
      std::map<std::pair<Index, Index>, Index> midpoint;
      auto mid = [&](Index a, Index b) {
        const auto key = std::minmax(a, b);
        auto it = midpoint.find(key);
        if (it != midpoint.end()) return it->second;
        p.push_back(((p[static_cast<std::size_t>(a)] + p[static_cast<std::size_t>(b)]) / 2).normalized());
        return midpoint[key] = static_cast<Index>(p.size() - 1);
      };
      std::vector<std::array<Index, 3>> g;
      for (const auto& t : f) {
        const Index ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
        g.push_back({t[0], ab, ca});
        g.push_back({ab, t[1], bc});
        g.push_back({ca, bc, t[2]});
        g.push_back({ab, bc, ca});
      }
      f = g;
    }
    auto positions = [&p] {
      std::vector<std::array<double, 3>> v;
      for (const auto& q : p) {
        const long double r = 1 + *uniform(-0.1, 0.1);
        v.push_back({static_cast<double>(r * q[0]), static_cast<double>(r * q[1]), static_cast<double>(r * q[2])});
      }
      return v;
    };
    MeshCase m;
    m.family = subdivide ? "closed sphere (subdivided octahedron)" : "closed sphere (octahedron)";
    m.deformed.faces = m.rest.faces = f;
    m.deformed.vertices = positions();
    m.rest.vertices = positions();
    return m;
  });
}

// Any mesh; every face non-degenerate (checked exactly), every hinge a valid hinge.
inline rc::Gen<MeshCase> mesh() {
  return rc::gen::suchThat(rc::gen::oneOf(grid_mesh(), torus_mesh(), sphere_mesh()), [](const MeshCase& m) {
    try {
      check_faces_nondegenerate(m.deformed);
      check_faces_nondegenerate(m.rest);
      build_topology(m.deformed);
      return true;
    } catch (const std::exception&) {
      return false;
    }
  });
}

// A relabelling of a mesh: a vertex permutation, a face permutation, and a cyclic rotation of each face
// (the same surface, the same orientation).
struct MeshRelabelling {
  std::vector<Index> vertex_map;  // new index of old vertex v
  std::vector<std::size_t> face_order;
  std::vector<int> rotation;  // per new face: 0, 1, 2
};

inline rc::Gen<MeshRelabelling> mesh_relabelling(std::size_t vertices, std::size_t faces) {
  return rc::gen::exec([vertices, faces] {
    MeshRelabelling r;
    auto shuffle = [](std::size_t n) {
      std::vector<std::size_t> p(n);
      std::iota(p.begin(), p.end(), 0);
      for (std::size_t i = n; i > 1; --i)
        std::swap(p[i - 1], p[static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, i))]);
      return p;
    };
    for (std::size_t v : shuffle(vertices)) r.vertex_map.push_back(static_cast<Index>(v));
    r.face_order = shuffle(faces);
    for (std::size_t f = 0; f < faces; ++f) r.rotation.push_back(*rc::gen::inRange(0, 3));
    return r;
  });
}

}  // namespace gen

inline void showValue(const gen::MeshRelabelling& r, std::ostream& os) {
  os << "vertex map";
  for (Index v : r.vertex_map) os << " " << v;
  os << "; face order";
  for (std::size_t f : r.face_order) os << " " << f;
  os << "; rotations";
  for (int k : r.rotation) os << " " << k;
}

inline Mesh relabel(const Mesh& m, const gen::MeshRelabelling& r) {
  Mesh out;
  out.vertices.resize(m.vertices.size());
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    out.vertices[static_cast<std::size_t>(r.vertex_map[v])] = m.vertices[v];
  for (std::size_t k = 0; k < m.faces.size(); ++k) {
    const auto& f = m.faces[r.face_order[k]];
    std::array<Index, 3> g;
    for (int i = 0; i < 3; ++i)
      g[static_cast<std::size_t>(i)] =
          r.vertex_map[static_cast<std::size_t>(f[static_cast<std::size_t>((i + r.rotation[k]) % 3)])];
    out.faces.push_back(g);
  }
  return out;
}

// Every face reversed: (a, b, c) -> (a, c, b).
inline Mesh reversed(const Mesh& m) {
  Mesh out = m;
  for (auto& f : out.faces) std::swap(f[1], f[2]);
  return out;
}

// A motion applied to every vertex (exact for signed permutations).
inline Mesh moved(const Mesh& m, const Motion& motion) {
  Mesh out = m;
  for (auto& v : out.vertices) {
    Coordinates x{};
    for (int c = 0; c < 3; ++c) x[static_cast<std::size_t>(c)] = v[static_cast<std::size_t>(c)];
    const Coordinates y = apply_motion(motion, x);
    for (int c = 0; c < 3; ++c) v[static_cast<std::size_t>(c)] = y[static_cast<std::size_t>(c)];
  }
  return out;
}

}  // namespace hinge::test
