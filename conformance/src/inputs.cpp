// The conformance inputs (hinge/conformance/inputs.hpp), built deterministically: a fixed-seed SplitMix64
// generator, IEEE-754 basic operations only (the project compiles with -ffp-contract=off, so that no
// platform fuses a multiply and an add), and sines and cosines from MPFR, correctly rounded. The same
// doubles therefore come out everywhere, and conformance/ can be regenerated bit for bit.
//
// Each hinge is built in a local frame, then rotated and translated:
//
//            x0 = (u0, h0, 0)                      upper triangle in the plane z = 0
//           /    .
//   x1 = 0 ------ x2 = (L0, 0, 0)                  hinge edge along +x
//           .    /
//            x3 = (u3, -h3 cos(psi), h3 sin(psi))  lower triangle rotated by psi about the hinge edge
//
// psi = 0 is flat (theta = 0), psi -> +-pi folds x3 onto the upper triangle's side; |theta| = |psi|.
#include <mpfr.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include "hinge/conformance/inputs.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/exact.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {
namespace {

using namespace oracle;  // the certifier: exact_hinge, certify, certified_mesh, ...

using X12 = std::array<double, 12>;
using P3 = std::array<double, 3>;
constexpr double pi = 3.141592653589793;  // the double nearest to pi

class Random {  // SplitMix64 (Steele, Lea & Flood 2014)
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }  // [0, 1), exact
  double uniform(double a, double b) { return a + (b - a) * unit(); }
  double sign() { return (next() >> 63) ? -1.0 : 1.0; }
  int integer(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }

 private:
  std::uint64_t state_;
};

// sin and cos of a double, correctly rounded (MPFR).
std::pair<double, double> sin_cos(double angle) {
  mpfr_t a, s, c;
  mpfr_inits2(53, a, s, c, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(a, angle, MPFR_RNDN);
  mpfr_sin_cos(s, c, a, MPFR_RNDN);
  const std::pair<double, double> r{mpfr_get_d(s, MPFR_RNDN), mpfr_get_d(c, MPFR_RNDN)};
  mpfr_clears(a, s, c, static_cast<mpfr_ptr>(nullptr));
  return r;
}

// 10^k, correctly rounded (std::from_chars rounds correctly and ignores the locale).
double power_of_ten(int k) {
  const std::string text = "1e" + std::to_string(k);
  double v = 0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

struct Local {  // the local frame of the file comment
  double L0 = 1, u0 = 0.5, h0 = 1, u3 = 0.5, h3 = 1;
  double sin_psi = 0, cos_psi = 1;
  void set_psi(double psi) { std::tie(sin_psi, cos_psi) = sin_cos(psi); }
  // psi = side * (pi - delta) for a small delta, without forming pi - delta.
  void set_folded(double delta, double side) {
    const auto [s, c] = sin_cos(delta);
    sin_psi = side * s;
    cos_psi = -c;
  }
  std::array<P3, 4> points() const {
    return {P3{u0, h0, 0}, P3{0, 0, 0}, P3{L0, 0, 0}, P3{u3, -h3 * cos_psi, h3 * sin_psi}};
  }
};

using Rotation = std::array<double, 9>;  // row-major
constexpr Rotation identity{1, 0, 0, 0, 1, 0, 0, 0, 1};

Rotation random_rotation(Random& r) {  // from a random unit quaternion
  double w, x, y, z, n2;
  do {
    w = r.uniform(-1, 1), x = r.uniform(-1, 1), y = r.uniform(-1, 1), z = r.uniform(-1, 1);
    n2 = w * w + x * x + y * y + z * z;
  } while (n2 > 1 || n2 < 0.0625);
  const double n = std::sqrt(n2);
  w /= n, x /= n, y /= n, z /= n;
  return {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
          2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
          2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
}

// x = scale * (R (p - center)) + offset, per vertex.
X12 place(const std::array<P3, 4>& p, const P3& center, const Rotation& R, double scale, const P3& offset) {
  X12 x{};
  for (int v = 0; v < 4; ++v) {
    const P3 d{p[v][0] - center[0], p[v][1] - center[1], p[v][2] - center[2]};
    for (int c = 0; c < 3; ++c) {
      const double rotated = R[3 * c] * d[0] + R[3 * c + 1] * d[1] + R[3 * c + 2] * d[2];
      x[3 * v + c] = scale * rotated + offset[c];
    }
  }
  return x;
}

P3 random_point(Random& r, double half_width) {
  return {r.uniform(-half_width, half_width), r.uniform(-half_width, half_width), r.uniform(-half_width, half_width)};
}

// Whether the exact hinge is valid and well-shaped with a margin (docs/contract.md: smallest altitude
// >= 0.15 longest edge in each triangle, 0.05 <= |theta| <= pi - 0.05; here 0.16 and 0.06, so that
// a double evaluation of the definition agrees). The altitude test is exact in integers.
bool well_shaped_exactly(const X12& x) {
  try {
    const ScaledHinge s = scale_exactly(x);
    auto vertex = [&s](int v) { return std::array<Int, 3>{s.X[3 * v], s.X[3 * v + 1], s.X[3 * v + 2]}; };
    auto sq = [](const std::array<Int, 3>& a, const std::array<Int, 3>& b) {
      Int d = 0;
      for (int c = 0; c < 3; ++c) d += (a[c] - b[c]) * (a[c] - b[c]);
      return d;
    };
    const ExactHinge e = exact_hinge(s, false);
    const auto x0 = vertex(0), x1 = vertex(1), x2 = vertex(2), x3 = vertex(3);
    const Int upper = std::max({sq(x2, x1), sq(x0, x2), sq(x1, x0)});
    const Int lower = std::max({sq(x2, x1), sq(x3, x2), sq(x1, x3)});
    // min altitude = |N| / l_max >= 0.16 l_max  <=>  nn >= 0.0256 l_max^4  <=>  625 nn >= 16 l_max^4
    if (625 * e.nn < 16 * upper * upper || 625 * e.tt < 16 * lower * lower) return false;
    const double theta = std::fabs(certify(exact_hinge(s, true)).theta);
    return theta >= 0.06 && theta <= pi - 0.06;
  } catch (const InputError&) {
    return false;
  } catch (const DomainError&) {
    return false;
  }
}

// Whether the hinge is valid and every output is a finite double (certified).
bool valid(const X12& x) {
  try {
    certified_theta_derivatives(x);
    return true;
  } catch (const InputError&) {
    return false;
  } catch (const DomainError&) {
    return false;
  }
}

std::string two_digits(int i) { return (i < 10 ? "0" : "") + std::to_string(i); }

class Builder {
 public:
  explicit Builder(std::vector<Case>& out) : out_(out) {}
  void start(const std::string& category) {
    category_ = category;
    index_ = 0;
  }
  void add(const std::string& tag, const X12& x) {
    if (!valid(x)) throw std::logic_error("conformance input " + category_ + "/" + tag + " is not valid");
    out_.push_back({category_ + "/" + two_digits(index_++) + "-" + tag, category_, x});
  }

 private:
  std::vector<Case>& out_;
  std::string category_;
  int index_ = 0;
};

// A random well-shaped local hinge.
Local random_well_shaped(Random& r) {
  Local l;
  l.u0 = r.uniform(0.25, 0.75), l.h0 = r.uniform(0.6, 1.3);
  l.u3 = r.uniform(0.25, 0.75), l.h3 = r.uniform(0.6, 1.3);
  l.set_psi(r.sign() * r.uniform(0.1, pi - 0.1));
  return l;
}

X12 random_placement(Random& r, const Local& l, double scale = 1) {
  return place(l.points(), {0.5 * l.L0, 0, 0}, random_rotation(r), scale, random_point(r, 1));
}

void well_shaped(Builder& b) {
  Random r(0x5eed0001);
  b.start("well-shaped");
  for (int i = 0; i < 40;) {
    const X12 x = random_placement(r, random_well_shaped(r), r.uniform(0.5, 2));
    if (!well_shaped_exactly(x)) continue;
    b.add("random", x);
    ++i;
  }
}

// Exact rotations: signed permutations of the axes with determinant +1.
const std::array<std::pair<const char*, Rotation>, 8> exact_rotations{{
    {"identity", identity},
    {"x90", {1, 0, 0, 0, 0, -1, 0, 1, 0}},
    {"y90", {0, 0, 1, 0, 1, 0, -1, 0, 0}},
    {"z90", {0, -1, 0, 1, 0, 0, 0, 0, 1}},
    {"x180", {1, 0, 0, 0, -1, 0, 0, 0, -1}},
    {"cycle", {0, 0, 1, 1, 0, 0, 0, 1, 0}},
    {"cycle2", {0, 1, 0, 0, 0, 1, 1, 0, 0}},
    {"z270", {0, 1, 0, -1, 0, 0, 0, 0, 1}},
}};

void rotations(Builder& b) {
  Random r(0x5eed0002);
  b.start("rotations");
  Local l;
  l.u0 = 0.375, l.h0 = 0.875, l.u3 = 0.625, l.h3 = 0.75;
  l.set_psi(1.125);
  const P3 center{0.5, 0.25, 0};
  for (const auto& [name, R] : exact_rotations) b.add(name, place(l.points(), center, R, 1, {0, 0, 0}));
  for (int i = 0; i < 22; ++i) b.add("random", place(l.points(), center, random_rotation(r), 1, {0, 0, 0}));
}

void scales(Builder& b) {
  Random r(0x5eed0003);
  b.start("scales");
  Local l;
  l.u0 = 0.4375, l.h0 = 0.8125, l.u3 = 0.5625, l.h3 = 0.9375;
  l.set_psi(-0.875);
  const Rotation R = random_rotation(r);
  const P3 offset = random_point(r, 0.5);
  const X12 base = place(l.points(), {0.5, 0, 0}, R, 1, offset);
  for (int k : {-500, -400, -300, -200, -100, -50, -10, 0, 10, 50, 100, 200, 300, 400, 500}) {
    X12 x = base;
    for (double& v : x) v = std::ldexp(v, k);
    b.add("2^" + std::to_string(k), x);
  }
  for (int k : {-150, -100, -50, -20, -5, 5, 20, 50, 100, 150}) {
    X12 x = base;
    const double f = power_of_ten(k);
    for (double& v : x) v *= f;
    b.add("1e" + std::to_string(k), x);
  }
  for (int i = 0; i < 5; ++i) {
    const int k = r.integer(-480, 480);
    const double f = std::ldexp(r.uniform(1, 2), k);
    X12 x = random_placement(r, random_well_shaped(r));
    for (double& v : x) v *= f;
    b.add("random-2^" + std::to_string(k), x);
  }
}

void offsets(Builder& b) {
  Random r(0x5eed0004);
  b.start("offsets");
  auto direction = [&r] {
    P3 d;
    double n2;
    do {
      d = random_point(r, 1);
      n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    } while (n2 > 1 || n2 < 0.0625);
    const double n = std::sqrt(n2);
    return P3{d[0] / n, d[1] / n, d[2] / n};
  };
  auto shifted = [&](double magnitude) {
    const Local l = random_well_shaped(r);
    const P3 d = direction();
    return place(l.points(), {0.5, 0, 0}, random_rotation(r), 1,
                 {magnitude * d[0], magnitude * d[1], magnitude * d[2]});
  };
  for (int k = 1; k <= 14; ++k) b.add("1e" + std::to_string(k), shifted(power_of_ten(k)));
  for (int k : {3, 10, 20, 30, 40}) {  // all three coordinates offset by the same power of two
    const Local l = random_well_shaped(r);
    const double o = std::ldexp(1.0, k);
    b.add("2^" + std::to_string(k), place(l.points(), {0.5, 0, 0}, random_rotation(r), 1, {o, -o, o}));
  }
  for (int i = 0; i < 11; ++i) {
    const int k = r.integer(0, 12);
    b.add("random-1e" + std::to_string(k), shifted(r.uniform(1, 10) * power_of_ten(k)));
  }
}

// Exactly coplanar hinges off the coordinate planes: integer points a u + b v in the lattice plane
// spanned by u = (1, 2, 2), v = (2, 1, -2) (u . v = 0, |u| = |v| = 3). `folded` puts x3 on x0's side.
X12 lattice_hinge(bool folded) {
  const std::array<int, 3> u{1, 2, 2}, v{2, 1, -2};
  auto point = [&](int a, int c) {
    return P3{static_cast<double>(a * u[0] + c * v[0]), static_cast<double>(a * u[1] + c * v[1]),
              static_cast<double>(a * u[2] + c * v[2])};
  };
  const std::array<P3, 4> p{point(1, 3), point(0, 0), point(3, 0), folded ? point(2, 1) : point(2, -2)};
  X12 x{};
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) x[3 * k + c] = p[k][c];
  return x;
}

void near_flat(Builder& b) {
  Random r(0x5eed0005);
  b.start("near-flat");
  for (int k = 1; k <= 14; ++k)
    for (double side : {1.0, -1.0}) {
      Local l = random_well_shaped(r);
      l.set_psi(side * power_of_ten(-k));
      b.add(std::string(side > 0 ? "+" : "-") + "1e-" + std::to_string(k), random_placement(r, l));
    }
  Local flat;
  flat.u0 = 0.375, flat.h0 = 1, flat.u3 = 0.75, flat.h3 = 0.5;
  b.add("exact-axes", place(flat.points(), {0, 0, 0}, identity, 1, {0, 0, 0}));
  b.add("exact-axes-offset", place(flat.points(), {0, 0, 0}, {0, 0, 1, 1, 0, 0, 0, 1, 0}, 1, {1024, -3, 0.5}));
  b.add("exact-lattice", lattice_hinge(false));
  X12 scaled = lattice_hinge(false);
  for (double& v : scaled) v = std::ldexp(v, -20) + 0.25;
  b.add("exact-lattice-scaled", scaled);
}

void near_folded(Builder& b) {
  Random r(0x5eed0006);
  b.start("near-folded");
  for (int k = 1; k <= 14; ++k)
    for (double side : {1.0, -1.0}) {
      Local l = random_well_shaped(r);
      l.u3 = r.uniform(0.3, 0.7);  // keep x3 off x0 when folded
      if (std::fabs(l.u3 - l.u0) < 0.1) l.u3 = l.u0 + 0.15;
      l.set_folded(power_of_ten(-k), side);
      b.add(std::string(side > 0 ? "+" : "-") + "(pi-1e-" + std::to_string(k) + ")", random_placement(r, l));
    }
  Local fold;
  fold.u0 = 0.375, fold.h0 = 1, fold.u3 = 0.75, fold.h3 = 0.5;
  fold.sin_psi = 0, fold.cos_psi = -1;  // theta = +pi exactly (the branch cut)
  b.add("exact-axes", place(fold.points(), {0, 0, 0}, identity, 1, {0, 0, 0}));
  b.add("exact-lattice", lattice_hinge(true));
  X12 scaled = lattice_hinge(true);
  for (double& v : scaled) v = std::ldexp(v, 30) - 7;
  b.add("exact-lattice-scaled", scaled);
}

void needles(Builder& b) {
  Random r(0x5eed0007);
  b.start("needles");
  const std::array<const char*, 5> kinds{"cap-upper", "cap-lower", "cap-both", "spike-upper", "spike-lower"};
  for (const char* kind : kinds)
    for (int k = 2; k <= 12; k += 2) {
      Local l = random_well_shaped(r);
      const double small = power_of_ten(-k) * r.uniform(1, 2);
      const std::string name(kind);
      if (name == "cap-upper" || name == "cap-both") l.h0 = small;  // x0 nearly on the hinge edge
      if (name == "cap-lower" || name == "cap-both") l.h3 = small;
      if (name == "spike-upper") l.h0 = 1 / small, l.u0 = r.uniform(0, 1);  // x0 far away: long thin triangle
      if (name == "spike-lower") l.h3 = 1 / small, l.u3 = r.uniform(0, 1);
      b.add(name + "-1e-" + std::to_string(k), random_placement(r, l));
    }
}

void short_hinge_edges(Builder& b) {
  Random r(0x5eed0008);
  b.start("short-hinge-edges");
  for (int k = 1; k <= 12; ++k)
    for (int variant = 0; variant < 2; ++variant) {
      Local l = random_well_shaped(r);
      l.L0 = power_of_ten(-k) * r.uniform(1, 2);
      l.u0 = l.L0 * r.uniform(-1, 2), l.u3 = l.L0 * r.uniform(-1, 2);  // x0, x3 at distance ~1
      b.add("1e-" + std::to_string(k), random_placement(r, l));
    }
  for (int k : {10, 20, 30, 40, 50, 60}) {
    Local l = random_well_shaped(r);
    l.L0 = std::ldexp(1.0, -k);
    l.u0 = 0, l.u3 = l.L0;
    // x1 at the origin, no offset: the hinge edge is far below the ulp of coordinates near 1.
    b.add("2^-" + std::to_string(k), place(l.points(), {0, 0, 0}, random_rotation(r), 1, {0, 0, 0}));
  }
}

void boundary_meshes(Builder& b) {
  b.start("boundary-meshes");
  for (const MeshCase& m : meshes()) {
    const Topology t = build_topology(m.deformed);
    for (std::size_t h = 0; h < t.hinges.size(); ++h)
      b.add(m.name + "-hinge" + std::to_string(h), hinge_coordinates(m.deformed, t.hinges[h]));
  }
}

// --- the hard families (hard_cases) ---------------------------------------------------------------

// Adds x under `family` unless it is not a valid hinge with finite certified outputs (a random draw can
// land on one: a needle whose apex rounds onto the hinge edge, say).
void add_if_valid(std::vector<Case>& out, const std::string& family, const std::string& tag, const X12& x) {
  if (!valid(x)) return;
  out.push_back({family + "/" + std::to_string(out.size()) + "-" + tag, family, x});
}

// theta's local hinge of the file comment with a small h0 (cap), a large h0 (spike), either on either
// side, or a cap above and a spike below.
X12 random_needle(Random& r, std::string& tag) {
  Local l = random_well_shaped(r);
  const int k = r.integer(2, 15);
  const double small = power_of_ten(-k) * r.uniform(1, 2);
  static const std::array<const char*, 6> kinds{"cap-upper",   "cap-lower",   "cap-both",
                                                "spike-upper", "spike-lower", "cap-spike"};
  const std::string kind = kinds[static_cast<std::size_t>(r.integer(0, 5))];
  if (kind == "cap-upper" || kind == "cap-both" || kind == "cap-spike") l.h0 = small;
  if (kind == "cap-lower" || kind == "cap-both") l.h3 = small;
  if (kind == "spike-upper") l.h0 = 1 / small, l.u0 = r.uniform(0, 1);
  if (kind == "spike-lower" || kind == "cap-spike") l.h3 = 1 / small, l.u3 = r.uniform(0, 1);
  tag = kind + "-1e-" + std::to_string(k);
  return random_placement(r, l);
}

// --- float32: the categories and the hard families within float32's range ----------------------------
//
// Every coordinate is a float (or zero), held in a double: the hinges are built as above and rounded to
// float (a conversion, correctly rounded to nearest-even by IEEE-754), which moves a vertex by up to 2^-24 of
// its magnitude. That keeps what a category is about where the feature is larger than the rounding (an
// angle, a height, a hinge edge above about 1e-5 of the coordinates); below that a hinge is built in an
// axis-aligned frame (the local frame of the file comment, a signed permutation of the axes, offsets only
// along axes where they cannot round the small feature away), so that the feature is a float of its own
// and survives exactly: angles to 1e-30, caps to 1e-12.

double to_float(double v) { return static_cast<double>(static_cast<float>(v)); }

X12 to_float(X12 x) {
  for (double& v : x) v = to_float(v);
  return x;
}

// Whether every coordinate is zero or a normal float (the rounding above gives floats; this excludes the
// subnormal ones).
bool normal_float_coordinates(const X12& x) {
  for (double v : x)
    if (v != 0 && !(std::fabs(v) >= 0x1p-126 && std::fabs(v) <= 0x1.fffffep127)) return false;
  return true;
}

// Whether x is a float32 case: float coordinates, a valid hinge, every output certified in binary32 a zero
// or a normal float.
bool valid_float32(const X12& x) {
  if (!normal_float_coordinates(x)) return false;
  Options binary32;
  binary32.binary32 = true;
  try {
    certified_theta_derivatives(x, binary32);
    return true;
  } catch (const InputError&) {
    return false;
  } catch (const DomainError&) {
    return false;
  }
}

// A random rotation of the axes (one of the 24 signed permutations with determinant +1): exact.
Rotation random_axes(Random& r) {
  static constexpr int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  const int k = r.integer(0, 5);
  const double s0 = r.sign(), s1 = r.sign();
  const double s2 = s0 * s1 * (k < 3 ? 1 : -1);  // odd permutations need an odd number of sign flips
  const double signs[3] = {s0, s1, s2};
  Rotation R{};
  for (int row = 0; row < 3; ++row) R[3 * row + orders[k][row]] = signs[row];
  return R;
}

// The local hinge in an axis-aligned frame, exactly: the local coordinates rounded to float, offset along
// local x always and along local y and z only where `offset_y`, `offset_z` (each sum rounded to float),
// then an exact rotation of the axes. A coordinate that is not offset keeps its float bits.
X12 axis_aligned(Random& r, const Local& l, bool offset_y, bool offset_z) {
  const P3 offset{to_float(r.uniform(-1, 1)), offset_y ? to_float(r.uniform(-1, 1)) : 0.0,
                  offset_z ? to_float(r.uniform(-1, 1)) : 0.0};
  std::array<P3, 4> p = l.points();
  for (P3& v : p)
    for (int c = 0; c < 3; ++c) v[c] = to_float(to_float(v[c]) + offset[c]);
  return place(p, {0, 0, 0}, random_axes(r), 1, {0, 0, 0});
}

class Builder32 {  // Builder with float32's rules: a fixed-list case must be valid, a random draw may be drawn again
 public:
  explicit Builder32(std::vector<Case>& out) : out_(out) {}
  void start(const std::string& category) {
    category_ = category;
    index_ = 0;
  }
  void add(const std::string& tag, const X12& x) {
    if (!valid_float32(x))
      throw std::logic_error("float32 conformance input " + category_ + "/" + tag + " is not valid");
    out_.push_back({category_ + "/" + two_digits(index_++) + "-" + tag, category_, x});
  }
  // Adds the first valid hinge of make() (bounded: a construction that fails 100 times in a row is a bug).
  template <class Make>
  void add_drawn(const std::string& tag, Make&& make) {
    for (int attempt = 0; attempt < 100; ++attempt) {
      const X12 x = make();
      if (valid_float32(x)) {
        add(tag, x);
        return;
      }
    }
    throw std::logic_error("float32 conformance input " + category_ + "/" + tag + ": no valid draw");
  }

 private:
  std::vector<Case>& out_;
  std::string category_;
  int index_ = 0;
};

// The constructions shared by the float32 categories and the float32 hard families.

// theta = side 10^-k u (u in [1, 2) when `jitter`): rotated and offset (then rounded) down to 1e-4, where the
// rounding moves theta by under 1e-3 of itself; in the axis-aligned frame below (no offset along local z).
X12 make_near_flat32(Random& r, int k, double side, bool jitter) {
  Local l = random_well_shaped(r);
  l.set_psi(side * power_of_ten(-k) * (jitter ? r.uniform(1, 2) : 1.0));
  return k <= 4 ? to_float(random_placement(r, l)) : axis_aligned(r, l, true, false);
}

// theta = side (pi - 10^-k u): likewise.
X12 make_near_folded32(Random& r, int k, double side, bool jitter) {
  Local l = random_well_shaped(r);
  l.u3 = r.uniform(0.3, 0.7);  // keep x3 off x0 when folded
  if (std::fabs(l.u3 - l.u0) < 0.1) l.u3 = l.u0 + 0.15;
  l.set_folded(power_of_ten(-k) * (jitter ? r.uniform(1, 2) : 1.0), side);
  return k <= 4 ? to_float(random_placement(r, l)) : axis_aligned(r, l, true, false);
}

// A cap (a height 10^-k u above the hinge edge) or a spike (a vertex 10^k / u away) of the given kind:
// caps rotated and offset down to 1e-4, axis-aligned below;
// spikes rotated and offset at every size (rounding moves the far vertex by 2^-24 of its distance).
// Axis-aligned caps are offset along the hinge edge only: the heights of x0 and x3 lie along local y and z.
X12 make_needle32(Random& r, const std::string& kind, int k) {
  Local l = random_well_shaped(r);
  const double small = power_of_ten(-k) * r.uniform(1, 2);
  if (kind == "cap-upper" || kind == "cap-both" || kind == "cap-spike") l.h0 = small;
  if (kind == "cap-lower" || kind == "cap-both") l.h3 = small;
  if (kind == "spike-upper") l.h0 = 1 / small, l.u0 = r.uniform(0, 1);
  if (kind == "spike-lower" || kind == "cap-spike") l.h3 = 1 / small, l.u3 = r.uniform(0, 1);
  if (kind.rfind("cap", 0) == 0 && k > 4) return axis_aligned(r, l, false, false);
  return to_float(random_placement(r, l));
}

// A hinge edge of length L0 = 2^-k u (u in [1, 2)) and the other vertices at distance about 1: offset
// (then rounded) while the rounding moves the edge's ends by under 1e-2 of its length (k <= 16), else with
// x1 at the origin and no offset (x2 = R (L0, 0, 0), its coordinates floats of their own).
X12 make_short_hinge_edge32(Random& r, int k) {
  Local l = random_well_shaped(r);
  l.L0 = std::ldexp(r.uniform(1, 2), -k);
  l.u0 = l.L0 * r.uniform(-1, 2), l.u3 = l.L0 * r.uniform(-1, 2);
  const P3 offset = k <= 16 ? random_point(r, 1) : P3{0, 0, 0};
  return to_float(place(l.points(), {0, 0, 0}, random_rotation(r), 1, offset));
}

// A random well-shaped hinge offset by `magnitude` in a random direction, rounded.
X12 make_offset32(Random& r, double magnitude) {
  const Local l = random_well_shaped(r);
  const P3 d = random_point(r, 1);
  return to_float(
      place(l.points(), {0.5, 0, 0}, random_rotation(r), 1, {magnitude * d[0], magnitude * d[1], magnitude * d[2]}));
}

X12 scaled_by_power_of_two(X12 x, int k) {
  for (double& v : x) v = std::ldexp(v, k);  // exact: float coordinates stay floats within the range
  return x;
}

const std::array<const char*, 6> needle_kinds{"cap-upper",   "cap-lower",   "cap-both",
                                              "spike-upper", "spike-lower", "cap-spike"};

void well_shaped32(Builder32& b) {
  Random r(0x5eed3201);
  b.start("well-shaped");
  for (int i = 0; i < 40;) {
    const X12 x = to_float(random_placement(r, random_well_shaped(r), r.uniform(0.5, 2)));
    if (!well_shaped_exactly(x) || !valid_float32(x)) continue;
    b.add("random", x);
    ++i;
  }
}

void rotations32(Builder32& b) {
  Random r(0x5eed3202);
  b.start("rotations");
  Local l;
  l.u0 = 0.375, l.h0 = 0.875, l.u3 = 0.625, l.h3 = 0.75;
  l.set_psi(1.125);
  const P3 center{0.5, 0.25, 0};
  for (const auto& [name, R] : exact_rotations) b.add(name, to_float(place(l.points(), center, R, 1, {0, 0, 0})));
  for (int i = 0; i < 22; ++i) b.add("random", to_float(place(l.points(), center, random_rotation(r), 1, {0, 0, 0})));
}

void scales32(Builder32& b) {
  Random r(0x5eed3203);
  b.start("scales");
  Local l;
  l.u0 = 0.4375, l.h0 = 0.8125, l.u3 = 0.5625, l.h3 = 0.9375;
  l.set_psi(-0.875);
  const X12 base = to_float(place(l.points(), {0.5, 0, 0}, random_rotation(r), 1, random_point(r, 0.5)));
  for (int k : {-50, -40, -30, -20, -10, -5, -1, 0, 1, 5, 10, 20, 30, 40, 50})
    b.add("2^" + std::to_string(k), scaled_by_power_of_two(base, k));
  for (int k : {-12, -10, -8, -5, -2, 2, 5, 8, 10, 12}) {
    X12 x = base;
    const double f = power_of_ten(k);
    for (double& v : x) v = to_float(v * f);
    b.add("1e" + std::to_string(k), x);
  }
  for (int i = 0; i < 5; ++i) {
    const int k = r.integer(-45, 45);
    b.add_drawn("random-2^" + std::to_string(k), [&] {
      X12 x = random_placement(r, random_well_shaped(r));
      const double f = std::ldexp(r.uniform(1, 2), k);
      for (double& v : x) v = to_float(v * f);
      return x;
    });
  }
}

void offsets32(Builder32& b) {
  Random r(0x5eed3204);
  b.start("offsets");
  for (int k = 1; k <= 6; ++k)
    for (int variant = 0; variant < 2; ++variant)
      b.add_drawn("1e" + std::to_string(k), [&] { return make_offset32(r, power_of_ten(k)); });
  for (int k : {3, 8, 12, 16, 20}) {  // all three coordinates offset by the same power of two
    b.add_drawn("2^" + std::to_string(k), [&] {
      const double o = std::ldexp(1.0, k);
      return to_float(place(random_well_shaped(r).points(), {0.5, 0, 0}, random_rotation(r), 1, {o, -o, o}));
    });
  }
  for (int i = 0; i < 13; ++i) {
    const int k = r.integer(0, 5);
    b.add_drawn("random-1e" + std::to_string(k), [&] { return make_offset32(r, r.uniform(1, 10) * power_of_ten(k)); });
  }
}

const std::array<int, 14> small_exponents32{1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 15, 20, 25, 30};

void near_flat32(Builder32& b) {
  Random r(0x5eed3205);
  b.start("near-flat");
  for (int k : small_exponents32)
    for (double side : {1.0, -1.0})
      b.add_drawn(std::string(side > 0 ? "+" : "-") + "1e-" + std::to_string(k),
                  [&] { return make_near_flat32(r, k, side, false); });
  Local flat;
  flat.u0 = 0.375, flat.h0 = 1, flat.u3 = 0.75, flat.h3 = 0.5;
  b.add("exact-axes", place(flat.points(), {0, 0, 0}, identity, 1, {0, 0, 0}));
  b.add("exact-axes-offset", place(flat.points(), {0, 0, 0}, {0, 0, 1, 1, 0, 0, 0, 1, 0}, 1, {1024, -3, 0.5}));
  b.add("exact-lattice", lattice_hinge(false));
  X12 scaled = lattice_hinge(false);
  for (double& v : scaled) v = std::ldexp(v, -20) + 0.25;  // at most 20 significant bits: floats
  b.add("exact-lattice-scaled", scaled);
}

void near_folded32(Builder32& b) {
  Random r(0x5eed3206);
  b.start("near-folded");
  for (int k : small_exponents32)
    for (double side : {1.0, -1.0})
      b.add_drawn(std::string(side > 0 ? "+" : "-") + "(pi-1e-" + std::to_string(k) + ")",
                  [&] { return make_near_folded32(r, k, side, false); });
  Local fold;
  fold.u0 = 0.375, fold.h0 = 1, fold.u3 = 0.75, fold.h3 = 0.5;
  fold.sin_psi = 0, fold.cos_psi = -1;  // theta = +pi exactly (the branch cut)
  b.add("exact-axes", place(fold.points(), {0, 0, 0}, identity, 1, {0, 0, 0}));
  b.add("exact-lattice", lattice_hinge(true));
  X12 scaled = lattice_hinge(true);
  for (double& v : scaled) v = std::ldexp(v, 10) - 7;  // integers below 2^24: floats
  b.add("exact-lattice-scaled", scaled);
}

void needles32(Builder32& b) {
  Random r(0x5eed3207);
  b.start("needles");
  for (int kind = 0; kind < 5; ++kind)
    for (int k = 2; k <= 12; k += 2)
      b.add_drawn(std::string(needle_kinds[kind]) + "-1e-" + std::to_string(k),
                  [&] { return make_needle32(r, needle_kinds[kind], k); });
}

void short_hinge_edges32(Builder32& b) {
  Random r(0x5eed3208);
  b.start("short-hinge-edges");
  for (int k = 2; k <= 60; k += 2)
    b.add_drawn("2^-" + std::to_string(k), [&] { return make_short_hinge_edge32(r, k); });
}

void boundary_meshes32(Builder32& b) {
  b.start("boundary-meshes");
  for (const MeshCase& m : meshes()) {
    const Topology t = build_topology(m.deformed);
    for (std::size_t h = 0; h < t.hinges.size(); ++h)
      b.add(m.name + "-hinge" + std::to_string(h), to_float(hinge_coordinates(m.deformed, t.hinges[h])));
  }
}

std::string four_digits(int i) {
  std::string s = std::to_string(i);
  return std::string(s.size() < 4 ? 4 - s.size() : 0, '0') + s;
}

// Re-identifies hard-family cases for a deep set: "<family>/deep-NNNN-<tag>", NNNN the case's index in its
// family (the ids of hard_cases number the draws across the families).
std::vector<Case> deep_ids(std::vector<Case> cases) {
  std::map<std::string, int> index;
  for (Case& c : cases) {
    const std::string tag = c.id.substr(c.id.find('-', c.id.find('/')) + 1);
    c.id = c.category + "/deep-" + four_digits(index[c.category]++) + "-" + tag;
  }
  return cases;
}

}  // namespace

const std::vector<std::string>& hard_families() {
  static const std::vector<std::string> names{"needles", "short-hinge-edges", "near-flat", "near-folded",
                                              "folded",  "offsets",           "scales",    "combined"};
  return names;
}

std::vector<Case> hard_cases(std::uint64_t seed, int per_family) {
  std::vector<Case> out;
  Random r(seed);
  for (int i = 0; i < per_family; ++i) {  // needles: caps and spikes down to 1e-15
    std::string tag;
    const X12 x = random_needle(r, tag);
    add_if_valid(out, "needles", tag, x);
  }
  for (int i = 0; i < per_family; ++i) {  // hinge edges from 2^-1 to 2^-60 of the others
    const int k = r.integer(1, 60);
    Local l = random_well_shaped(r);
    l.L0 = std::ldexp(r.uniform(1, 2), -k);
    l.u0 = l.L0 * r.uniform(-1, 2), l.u3 = l.L0 * r.uniform(-1, 2);
    // Beyond 2^-40 the hinge edge must sit near the origin to be representable apart from its neighbours.
    const P3 offset = k > 40 ? P3{0, 0, 0} : random_point(r, 1);
    add_if_valid(out, "short-hinge-edges", "2^-" + std::to_string(k),
                 place(l.points(), {0, 0, 0}, random_rotation(r), 1, offset));
  }
  for (int i = 0; i < per_family; ++i) {  // |theta| from 1e-1 to 1e-15
    const int k = r.integer(1, 15);
    Local l = random_well_shaped(r);
    l.set_psi(r.sign() * power_of_ten(-k) * r.uniform(1, 2));
    add_if_valid(out, "near-flat", "1e-" + std::to_string(k), random_placement(r, l));
  }
  for (int i = 0; i < per_family; ++i) {  // |theta| from pi - 1e-1 to pi - 1e-15
    const int k = r.integer(1, 15);
    Local l = random_well_shaped(r);
    l.u3 = r.uniform(0.3, 0.7);
    if (std::fabs(l.u3 - l.u0) < 0.1) l.u3 = l.u0 + 0.15;
    l.set_folded(power_of_ten(-k) * r.uniform(1, 2), r.sign());
    add_if_valid(out, "near-folded", "pi-1e-" + std::to_string(k), random_placement(r, l));
  }
  for (int i = 0; i < per_family; ++i) {  // exactly folded (theta = +pi) or flat, on lattice planes, scaled
    X12 x = lattice_hinge(i % 2 == 0);
    const int k = r.integer(-300, 300);
    const double o = std::ldexp(static_cast<double>(r.integer(-64, 64)), k);
    for (double& v : x) v = std::ldexp(v, k) + o;
    add_if_valid(out, "folded", std::string(i % 2 == 0 ? "folded" : "flat") + "-2^" + std::to_string(k), x);
  }
  for (int i = 0; i < per_family; ++i) {  // offsets from 1 to 1e16 times the hinge's size
    const int k = r.integer(0, 15);
    const Local l = random_well_shaped(r);
    const P3 d = random_point(r, 1);
    const double o = power_of_ten(k) * r.uniform(1, 10);
    add_if_valid(out, "offsets", "1e" + std::to_string(k),
                 place(l.points(), {0.5, 0, 0}, random_rotation(r), 1, {o * d[0], o * d[1], o * d[2]}));
  }
  for (int i = 0; i < per_family; ++i) {  // scales 2^-500 to 2^500
    const int k = r.integer(-500, 500);
    X12 x = random_placement(r, random_well_shaped(r));
    for (double& v : x) v = std::ldexp(v, k);
    add_if_valid(out, "scales", "2^" + std::to_string(k), x);
  }
  for (int i = 0; i < per_family; ++i) {  // a needle, offset and scaled
    std::string tag;
    X12 x = random_needle(r, tag);
    const double o = power_of_ten(r.integer(0, 8));
    const P3 d = random_point(r, 1);
    const int k = r.integer(-300, 300);
    for (int v = 0; v < 4; ++v)
      for (int c = 0; c < 3; ++c) x[3 * v + c] = std::ldexp(x[3 * v + c] + o * d[c], k);
    add_if_valid(out, "combined",
                 tag + "-offset-1e" + std::to_string(static_cast<int>(std::log10(o))) + "-2^" + std::to_string(k), x);
  }
  return out;
}

std::vector<Case> deep_inputs() { return deep_ids(hard_cases(deep_seed, deep_per_family)); }

std::vector<Case> hard_cases_float32(std::uint64_t seed, int per_family) {
  std::vector<Case> out;
  Random r(seed);
  auto add = [&out](const std::string& family, const std::string& tag, const X12& x) {
    if (valid_float32(x)) out.push_back({family + "/" + std::to_string(out.size()) + "-" + tag, family, x});
  };
  for (int i = 0; i < per_family; ++i) {  // needles: caps to 1e-12, spikes to 1e12
    const std::string kind = needle_kinds[static_cast<std::size_t>(r.integer(0, 5))];
    const int k = r.integer(2, 12);
    add("needles", kind + "-1e-" + std::to_string(k), make_needle32(r, kind, k));
  }
  for (int i = 0; i < per_family; ++i) {  // hinge edges from 2^-1 to 2^-60 of the others
    const int k = r.integer(1, 60);
    add("short-hinge-edges", "2^-" + std::to_string(k), make_short_hinge_edge32(r, k));
  }
  for (int i = 0; i < per_family; ++i) {  // |theta| from 1e-1 to 1e-30
    const int k = r.integer(1, 30);
    add("near-flat", "1e-" + std::to_string(k), make_near_flat32(r, k, r.sign(), true));
  }
  for (int i = 0; i < per_family; ++i) {  // |theta| from pi - 1e-1 to pi - 1e-30
    const int k = r.integer(1, 30);
    add("near-folded", "pi-1e-" + std::to_string(k), make_near_folded32(r, k, r.sign(), true));
  }
  for (int i = 0; i < per_family; ++i) {  // exactly folded (theta = +pi) or flat, lattice planes, scaled
    X12 x = lattice_hinge(i % 2 == 0);
    const int k = r.integer(-40, 40);
    const double o = std::ldexp(static_cast<double>(r.integer(-64, 64)), k);
    for (double& v : x) v = std::ldexp(v, k) + o;  // at most 8 significant bits: floats
    add("folded", std::string(i % 2 == 0 ? "folded" : "flat") + "-2^" + std::to_string(k), x);
  }
  for (int i = 0; i < per_family; ++i) {  // offsets from 1 to 1e6 times the hinge's size
    const int k = r.integer(0, 5);
    add("offsets", "1e" + std::to_string(k), make_offset32(r, power_of_ten(k) * r.uniform(1, 10)));
  }
  for (int i = 0; i < per_family; ++i) {  // scales 2^-50 to 2^50
    const int k = r.integer(-50, 50);
    add("scales", "2^" + std::to_string(k),
        scaled_by_power_of_two(to_float(random_placement(r, random_well_shaped(r))), k));
  }
  for (int i = 0; i < per_family; ++i) {  // a needle (to 1e-4: rotated), offset and scaled
    const std::string kind = needle_kinds[static_cast<std::size_t>(r.integer(0, 5))];
    const int k = r.integer(2, 4);
    X12 x = make_needle32(r, kind, k);
    const int j = r.integer(0, 5 - k);  // offset 10^j: rounding moves a cap of 10^-k by under 1e-2 of it
    const double o = power_of_ten(j);
    const P3 d = random_point(r, 1);
    const int e = r.integer(-40, 40);
    for (int v = 0; v < 4; ++v)
      for (int c = 0; c < 3; ++c) x[3 * v + c] = std::ldexp(to_float(x[3 * v + c] + o * d[c]), e);
    add("combined", kind + "-1e-" + std::to_string(k) + "-offset-1e" + std::to_string(j) + "-2^" + std::to_string(e),
        x);
  }
  return out;
}

std::vector<Case> deep_float32_inputs() { return deep_ids(hard_cases_float32(deep_seed, deep_per_family)); }

std::vector<Case> float32_inputs() {
  std::vector<Case> cases;
  Builder32 b(cases);
  well_shaped32(b);
  rotations32(b);
  scales32(b);
  offsets32(b);
  near_flat32(b);
  near_folded32(b);
  needles32(b);
  short_hinge_edges32(b);
  boundary_meshes32(b);
  return cases;
}

const std::vector<std::string>& categories() {
  static const std::vector<std::string> names{"well-shaped", "rotations",         "scales",
                                              "offsets",     "near-flat",         "near-folded",
                                              "needles",     "short-hinge-edges", "boundary-meshes"};
  return names;
}

std::vector<Case> inputs() {
  std::vector<Case> cases;
  Builder b(cases);
  well_shaped(b);
  rotations(b);
  scales(b);
  offsets(b);
  near_flat(b);
  near_folded(b);
  needles(b);
  short_hinge_edges(b);
  boundary_meshes(b);
  return cases;
}

// Two open meshes: a strip bent around a cylinder, and a hexagonal patch bulged into a cap with a
// twist; both rest flat. Vertices are grid points, moved by correctly rounded sines and cosines.
std::vector<MeshCase> meshes() {
  std::vector<MeshCase> out;
  {  // strip: (nx + 1) x (ny + 1) grid, spacing 1/2, bent about the y axis with radius 2
    MeshCase m;
    m.name = "strip";
    const int nx = 5, ny = 2;
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const double u = 0.5 * i - 1.25, v = 0.5 * j - 0.5;
        m.rest.vertices.push_back({u, v, 0});
        const auto [s, c] = sin_cos(u / 2);
        const auto [s2, c2] = sin_cos(3 * v + u);
        m.deformed.vertices.push_back({2 * s, v + 0.0625 * c2, 2 - 2 * c + 0.125 * s2});
      }
    auto id = [nx](int i, int j) { return static_cast<Index>(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const bool flip = (i + j) % 2 == 1;  // alternate the diagonals
        if (!flip) {
          m.rest.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
          m.rest.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        } else {
          m.rest.faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
          m.rest.faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        }
      }
    m.deformed.faces = m.rest.faces;
    out.push_back(std::move(m));
  }
  {  // hex: the 19 points of a hexagon of radius 2 in the triangular lattice, 24 faces
    MeshCase m;
    m.name = "hex";
    std::vector<std::pair<int, int>> lattice;  // axial coordinates (q, r), |q|, |r|, |q + r| <= 2
    for (int r = -2; r <= 2; ++r)
      for (int q = -2; q <= 2; ++q)
        if (std::abs(q + r) <= 2) lattice.emplace_back(q, r);
    auto find = [&lattice](int q, int r) -> Index {
      for (std::size_t k = 0; k < lattice.size(); ++k)
        if (lattice[k] == std::pair<int, int>{q, r}) return static_cast<Index>(k);
      return -1;
    };
    const double half_sqrt3 = 0.8660254037844386;  // sqrt(3)/2, correctly rounded
    for (const auto& [q, r] : lattice) {
      const double x = q + 0.5 * r, y = half_sqrt3 * r;
      m.rest.vertices.push_back({x, y, 0});
      const double r2 = x * x + y * y;
      const auto [s, c] = sin_cos(0.25 * x - 0.375 * y);
      m.deformed.vertices.push_back({x + 0.0625 * s, y - 0.0625 * c * s, 0.75 - 0.1875 * r2 + 0.125 * s});
    }
    for (const auto& [q, r] : lattice) {  // two triangles per lattice rhombus, counter-clockwise in z
      const Index a = find(q, r), b = find(q + 1, r), c = find(q, r + 1), d = find(q + 1, r - 1);
      if (b >= 0 && c >= 0) m.rest.faces.push_back({a, b, c});
      if (b >= 0 && d >= 0) m.rest.faces.push_back({a, d, b});
    }
    m.deformed.faces = m.rest.faces;
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace hinge::conformance
