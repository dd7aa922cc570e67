// conformance/src/construction.hpp (private to hinge::conformance): what the generators of the
// conformance inputs (inputs.cpp) and of the energy cases (energy_inputs.cpp) build hinges with: a
// fixed-seed SplitMix64 generator, correctly rounded sines and cosines (MPFR), the local frame of
// inputs.cpp's comment, exact and random rotations, placement. IEEE-754 basic operations only (the project
// compiles with -ffp-contract=off): the same doubles on every platform.
#pragma once

#include <mpfr.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>

namespace hinge::conformance::construction {

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
inline std::pair<double, double> sin_cos(double angle) {
  mpfr_t a, s, c;
  mpfr_inits2(53, a, s, c, static_cast<mpfr_ptr>(nullptr));
  mpfr_set_d(a, angle, MPFR_RNDN);
  mpfr_sin_cos(s, c, a, MPFR_RNDN);
  const std::pair<double, double> r{mpfr_get_d(s, MPFR_RNDN), mpfr_get_d(c, MPFR_RNDN)};
  mpfr_clears(a, s, c, static_cast<mpfr_ptr>(nullptr));
  return r;
}

// 10^k, correctly rounded (std::from_chars rounds correctly and ignores the locale).
inline double power_of_ten(int k) {
  const std::string text = "1e" + std::to_string(k);
  double v = 0;
  std::from_chars(text.data(), text.data() + text.size(), v);
  return v;
}

struct Local {  // the local frame of inputs.cpp's comment
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

inline Rotation random_rotation(Random& r) {  // from a random unit quaternion
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

// A random rotation of the axes (one of the 24 signed permutations with determinant +1): exact.
inline Rotation random_axes(Random& r) {
  static constexpr int orders[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  const int k = r.integer(0, 5);
  const double s0 = r.sign(), s1 = r.sign();
  const double s2 = s0 * s1 * (k < 3 ? 1 : -1);  // odd permutations need an odd number of sign flips
  const double signs[3] = {s0, s1, s2};
  Rotation R{};
  for (int row = 0; row < 3; ++row) R[3 * row + orders[k][row]] = signs[row];
  return R;
}

// Exact rotations: signed permutations of the axes with determinant +1.
inline const std::array<std::pair<const char*, Rotation>, 8> exact_rotations{{
    {"identity", identity},
    {"x90", {1, 0, 0, 0, 0, -1, 0, 1, 0}},
    {"y90", {0, 0, 1, 0, 1, 0, -1, 0, 0}},
    {"z90", {0, -1, 0, 1, 0, 0, 0, 0, 1}},
    {"x180", {1, 0, 0, 0, -1, 0, 0, 0, -1}},
    {"cycle", {0, 0, 1, 1, 0, 0, 0, 1, 0}},
    {"cycle2", {0, 1, 0, 0, 0, 1, 1, 0, 0}},
    {"z270", {0, 1, 0, -1, 0, 0, 0, 0, 1}},
}};

// x = scale * (R (p - center)) + offset, per vertex.
inline X12 place(const std::array<P3, 4>& p, const P3& center, const Rotation& R, double scale, const P3& offset) {
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

inline P3 random_point(Random& r, double half_width) {
  return {r.uniform(-half_width, half_width), r.uniform(-half_width, half_width), r.uniform(-half_width, half_width)};
}

// A random unit vector (a random point of the unit ball's shell 1/4 <= |d| <= 1, normalized).
inline P3 random_direction(Random& r) {
  P3 d;
  double n2;
  do {
    d = random_point(r, 1);
    n2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  } while (n2 > 1 || n2 < 0.0625);
  const double n = std::sqrt(n2);
  return P3{d[0] / n, d[1] / n, d[2] / n};
}

// l about its hinge edge's midpoint, times `scale`, under a random rotation and a random offset in [-1, 1]^3
// (drawn first).
inline X12 random_placement(Random& r, const Local& l, double scale = 1) {
  const P3 offset = random_point(r, 1);
  return place(l.points(), {0.5 * l.L0, 0, 0}, random_rotation(r), scale, offset);
}

inline X12 times(X12 x, double factor) {
  for (double& v : x) v *= factor;
  return x;
}

inline X12 scaled_by_power_of_two(X12 x, int k) {
  for (double& v : x) v = std::ldexp(v, k);  // exact within the range (float coordinates stay floats)
  return x;
}

}  // namespace hinge::conformance::construction
