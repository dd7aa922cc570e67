// The conformance inputs (hinge/conformance/inputs.hpp), built deterministically: a fixed-seed SplitMix64
// generator, IEEE-754 basic operations only (the project compiles with -ffp-contract=off, so that no
// platform fuses a multiply and an add), and sines and cosines from MPFR, correctly rounded. Every random
// draw is a statement of its own or the only draw of its expression: C++ leaves the order in which a call's
// arguments are evaluated unspecified (compilers differ), and the committed vectors fix one order. The same
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
//
// Each category and each hard family is written once, for both number formats (Format): the double sets
// and the float32 ones, whose hinges are built the same way within float32's range and rounded to float.
#include <mpfr.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "construction.hpp"
#include "hinge/conformance/inputs.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/exact.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {
namespace {

using namespace oracle;  // the certifier: exact_hinge, certify, certified_mesh, ...

using namespace construction;  // construction.hpp: the generator, the local frame, rotations, placement

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

// --- the rules of the sets ----------------------------------------------------------------------------

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

// Whether every coordinate is zero or a normal float (to_float gives floats; this excludes the subnormal
// ones).
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

// --- the two formats ----------------------------------------------------------------------------------
//
// The float32 hinges are built as the double ones, within float32's range, and rounded to float (a
// conversion, correctly rounded to nearest-even by IEEE-754), which moves a vertex by up to 2^-24 of its
// magnitude. That keeps what a category is about where the feature is larger than the rounding (an angle, a
// height, a hinge edge above about 1e-5 of the coordinates); below that a hinge is built in an axis-aligned
// frame (the local frame of the file comment, a signed permutation of the axes, offsets only along axes
// where they cannot round the small feature away), so that the feature is a float of its own and survives
// exactly: angles to 1e-30, caps to 1e-12.

X12 to_double(X12 x) { return x; }  // the hinges are built in double: nothing to round

double to_float(double v) { return static_cast<double>(static_cast<float>(v)); }

X12 to_float(X12 x) {
  for (double& v : x) v = to_float(v);
  return x;
}

// A set's number format: its rule, its rounding, its seeds and the ranges its hinges are built within
// (docs/conformance.md, docs/conformance-format.md "float32 sets", docs/hard-cases.md).
struct Format {
  const char* set;            // names the set in the message of a case that breaks its rule
  bool float32;               // selects the few draws that the float32 sets make in another order or way
  bool (*valid)(const X12&);  // the rule every case obeys
  X12 (*round)(X12);          // applied to a hinge placed in space: to_double (nothing) or to_float
  int rotated_to;             // a feature of 10^-k (angle, cap) rotated and offset for k <= this, else axis-aligned
  int short_edge_offset_to;   // a hinge edge of 2^-k u offset at random for k <= this, else at the origin

  // The quick set: category i (report order, from 1) draws from seed + i.
  std::uint64_t seed;
  std::array<int, 15> scale_twos;       // scales: one hinge times 2^k,
  std::array<int, 10> scale_tens;       // times 10^k,
  int random_scale_to;                  // and 5 random hinges times 2^k u (u in [1, 2)), |k| <= this
  int offset_tens;                      // offsets: 10^k in a random direction, k = 1 ... this,
  int per_offset_ten;                   // that many hinges each,
  std::array<int, 5> offset_twos;       // (2^k, -2^k, 2^k),
  int random_offsets;                   // and that many hinges offset 10^k u (u in [1, 10)),
  int random_offset_to;                 // k = 0 ... this
  std::array<int, 14> small_exponents;  // near-flat, near-folded: theta = +-10^-k, +-(pi - 10^-k)
  int folded_lattice_exponent;          // near-folded: the folded lattice hinge times 2^this, minus 7

  // The hard families.
  int needles_to;           // caps of 10^-k and spikes of 10^k, k = 2 ... this
  int angles_to;            // near-flat, near-folded: 10^-k u from flat or folded, k = 1 ... this
  int folded_scale;         // folded: times 2^k, |k| <= this
  int offsets_to;           // offsets: 10^k u (u in [1, 10)), k = 0 ... this
  int scales_to;            // scales: times 2^k, |k| <= this
  int combined_needles_to;  // combined: needles of 10^-k, k = 2 ... this,
  int combined_scale;       // offset, then times 2^k, |k| <= this
};

constexpr Format float64_format{
    .set = "conformance",
    .float32 = false,
    .valid = valid,
    .round = to_double,
    .rotated_to = std::numeric_limits<int>::max(),  // every feature placed at random
    // Beyond 2^-40 the hinge edge must sit near the origin to be representable apart from its neighbours.
    .short_edge_offset_to = 40,
    .seed = 0x5eed0000,
    .scale_twos = {-500, -400, -300, -200, -100, -50, -10, 0, 10, 50, 100, 200, 300, 400, 500},
    .scale_tens = {-150, -100, -50, -20, -5, 5, 20, 50, 100, 150},
    .random_scale_to = 480,
    .offset_tens = 14,
    .per_offset_ten = 1,
    .offset_twos = {3, 10, 20, 30, 40},
    .random_offsets = 11,
    .random_offset_to = 12,
    .small_exponents = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14},
    .folded_lattice_exponent = 30,
    .needles_to = 15,
    .angles_to = 15,
    .folded_scale = 300,
    .offsets_to = 15,
    .scales_to = 500,
    .combined_needles_to = 15,
    .combined_scale = 300,
};

constexpr Format float32_format{
    .set = "float32 conformance",
    .float32 = true,
    .valid = valid_float32,
    .round = to_float,
    .rotated_to = 4,  // the rounding moves theta, a cap, by under 1e-3 of itself down to 1e-4
    // Up to 2^-16 the rounding moves the edge's ends by under 1e-2 of its length; below, x1 = 0 and
    // x2 = R (L0, 0, 0) round on the edge's own scale.
    .short_edge_offset_to = 16,
    .seed = 0x5eed3200,
    .scale_twos = {-50, -40, -30, -20, -10, -5, -1, 0, 1, 5, 10, 20, 30, 40, 50},
    .scale_tens = {-12, -10, -8, -5, -2, 2, 5, 8, 10, 12},
    .random_scale_to = 45,
    .offset_tens = 6,
    .per_offset_ten = 2,
    .offset_twos = {3, 8, 12, 16, 20},
    .random_offsets = 13,
    .random_offset_to = 5,
    .small_exponents = {1, 2, 3, 4, 5, 6, 7, 8, 10, 12, 15, 20, 25, 30},
    .folded_lattice_exponent = 10,  // integers below 2^24: floats
    .needles_to = 12,
    .angles_to = 30,
    .folded_scale = 40,
    .offsets_to = 5,
    .scales_to = 50,
    .combined_needles_to = 4,  // caps placed at random, not axis-aligned
    .combined_scale = 40,
};

// --- the constructions --------------------------------------------------------------------------------

// A random well-shaped local hinge.
Local random_well_shaped(Random& r) {
  Local l;
  l.u0 = r.uniform(0.25, 0.75), l.h0 = r.uniform(0.6, 1.3);
  l.u3 = r.uniform(0.25, 0.75), l.h3 = r.uniform(0.6, 1.3);
  const double side = r.sign();
  l.set_psi(side * r.uniform(0.1, pi - 0.1));
  return l;
}

// A random well-shaped local hinge whose x3 stays off x0 when folded.
Local random_foldable(Random& r) {
  Local l = random_well_shaped(r);
  l.u3 = r.uniform(0.3, 0.7);
  if (std::fabs(l.u3 - l.u0) < 0.1) l.u3 = l.u0 + 0.15;
  return l;
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

// l with a feature of 10^-k (an angle from flat or folded, a cap): placed at random and rounded where the
// format keeps the feature that way, else axis-aligned, never offset along local z and along local y only
// when `offset_y` (an angle lies along local z, a cap's heights along local y and z).
X12 place_feature(Random& r, const Format& f, const Local& l, int k, bool offset_y) {
  if (k > f.rotated_to) return axis_aligned(r, l, offset_y, false);
  return f.round(random_placement(r, l));
}

// theta = side 10^-k u from l (u = 1, or drawn from [1, 2) when `jitter`).
X12 near_flat_hinge(Random& r, const Format& f, Local l, int k, double side, bool jitter) {
  l.set_psi(side * power_of_ten(-k) * (jitter ? r.uniform(1, 2) : 1.0));
  return place_feature(r, f, l, k, true);
}

// theta = side (pi - 10^-k u) from l (from random_foldable; u as above).
X12 near_folded_hinge(Random& r, const Format& f, Local l, int k, double side, bool jitter) {
  l.set_folded(power_of_ten(-k) * (jitter ? r.uniform(1, 2) : 1.0), side);
  return place_feature(r, f, l, k, true);
}

const std::array<const char*, 6> needle_kinds{"cap-upper",   "cap-lower",   "cap-both",
                                              "spike-upper", "spike-lower", "cap-spike"};

// l made a needle of the given kind, `small` = 10^-k u: a cap (a height `small` above the hinge edge), a
// spike (a vertex 1 / small away: a long thin triangle), either on either side, or a cap above and a spike
// below. Caps are placed as features of 10^-k; spikes at random at every size (rounding moves the far
// vertex by 2^-24 of its distance).
X12 needle(Random& r, const Format& f, Local l, const std::string& kind, int k, double small) {
  if (kind == "cap-upper" || kind == "cap-both" || kind == "cap-spike") l.h0 = small;  // x0 nearly on the edge
  if (kind == "cap-lower" || kind == "cap-both") l.h3 = small;
  if (kind == "spike-upper") l.h0 = 1 / small, l.u0 = r.uniform(0, 1);  // x0 far away
  if (kind == "spike-lower" || kind == "cap-spike") l.h3 = 1 / small, l.u3 = r.uniform(0, 1);
  if (kind.rfind("cap", 0) == 0) return place_feature(r, f, l, k, false);
  return f.round(random_placement(r, l));
}

// A needle of the given kind at 10^-k from a random well-shaped hinge.
X12 random_needle(Random& r, const Format& f, const std::string& kind, int k) {
  const Local l = random_well_shaped(r);
  const double small = power_of_ten(-k) * r.uniform(1, 2);
  return needle(r, f, l, kind, k, small);
}

// A hinge edge of length L0 = 2^-k u (u in [1, 2)) with x0 and x3 at distance about 1: offset at random for
// k <= f.short_edge_offset_to, else with x1 at the origin and no offset.
X12 short_hinge_edge(Random& r, const Format& f, int k) {
  Local l = random_well_shaped(r);
  l.L0 = std::ldexp(r.uniform(1, 2), -k);
  l.u0 = l.L0 * r.uniform(-1, 2), l.u3 = l.L0 * r.uniform(-1, 2);
  const P3 offset = k <= f.short_edge_offset_to ? random_point(r, 1) : P3{0, 0, 0};
  return f.round(place(l.points(), {0, 0, 0}, random_rotation(r), 1, offset));
}

// l rotated at random about its hinge edge's midpoint (L0 = 1) and translated by m d.
X12 translated(Random& r, const Local& l, double m, const P3& d) {
  return place(l.points(), {0.5, 0, 0}, random_rotation(r), 1, {m * d[0], m * d[1], m * d[2]});
}

// A random well-shaped hinge translated by m in a random direction: a unit vector, or (float32) a random
// point of [-1, 1]^3.
X12 offset_hinge(Random& r, const Format& f, double m) {
  const Local l = random_well_shaped(r);
  const P3 d = f.float32 ? random_point(r, 1) : random_direction(r);
  return f.round(translated(r, l, m, d));
}

// --- the categories (inputs, float32_inputs) ----------------------------------------------------------

std::string two_digits(int i) { return (i < 10 ? "0" : "") + std::to_string(i); }

std::string signed_tag(double side, const std::string& tag) { return (side > 0 ? "+" : "-") + tag; }

// Numbers the cases of a category and checks each against the format's rule.
class Builder {
 public:
  Builder(std::vector<Case>& out, const Format& format) : out_(out), format_(format) {}
  const Format& format() const { return format_; }
  void start(const std::string& category) {
    category_ = category;
    index_ = 0;
  }
  void add(const std::string& tag, const X12& x) {
    if (!format_.valid(x))
      throw std::logic_error(std::string(format_.set) + " input " + category_ + "/" + tag + " is not valid");
    out_.push_back({category_ + "/" + two_digits(index_++) + "-" + tag, category_, x, std::nullopt});
  }
  // Adds the first valid hinge of make() (bounded: a construction that fails 100 times in a row is a bug).
  template <class Make>
  void add_drawn(const std::string& tag, Make&& make) {
    for (int attempt = 0; attempt < 100; ++attempt) {
      const X12 x = make();
      if (format_.valid(x)) {
        add(tag, x);
        return;
      }
    }
    throw std::logic_error(std::string(format_.set) + " input " + category_ + "/" + tag + ": no valid draw");
  }

 private:
  std::vector<Case>& out_;
  const Format& format_;
  std::string category_;
  int index_ = 0;
};

void well_shaped(Builder& b) {
  const Format& f = b.format();
  Random r(f.seed + 1);
  b.start("well-shaped");
  for (int i = 0; i < 40;) {
    const double scale = r.uniform(0.5, 2);
    const Local l = random_well_shaped(r);
    const X12 x = f.round(random_placement(r, l, scale));
    if (!well_shaped_exactly(x) || !f.valid(x)) continue;
    b.add("random", x);
    ++i;
  }
}

void rotations(Builder& b) {
  const Format& f = b.format();
  Random r(f.seed + 2);
  b.start("rotations");
  Local l;
  l.u0 = 0.375, l.h0 = 0.875, l.u3 = 0.625, l.h3 = 0.75;
  l.set_psi(1.125);
  const P3 center{0.5, 0.25, 0};
  for (const auto& [name, R] : exact_rotations) b.add(name, f.round(place(l.points(), center, R, 1, {0, 0, 0})));
  for (int i = 0; i < 22; ++i) b.add("random", f.round(place(l.points(), center, random_rotation(r), 1, {0, 0, 0})));
}

void scales(Builder& b) {
  const Format& f = b.format();
  Random r(f.seed + 3);
  b.start("scales");
  Local l;
  l.u0 = 0.4375, l.h0 = 0.8125, l.u3 = 0.5625, l.h3 = 0.9375;
  l.set_psi(-0.875);
  Rotation R;
  P3 offset;
  if (f.float32) {  // draws the offset first
    offset = random_point(r, 0.5);
    R = random_rotation(r);
  } else {
    R = random_rotation(r);
    offset = random_point(r, 0.5);
  }
  const X12 base = f.round(place(l.points(), {0.5, 0, 0}, R, 1, offset));
  for (int k : f.scale_twos) b.add("2^" + std::to_string(k), scaled_by_power_of_two(base, k));
  for (int k : f.scale_tens) b.add("1e" + std::to_string(k), f.round(times(base, power_of_ten(k))));
  for (int i = 0; i < 5; ++i) {
    const int k = r.integer(-f.random_scale_to, f.random_scale_to);
    b.add_drawn("random-2^" + std::to_string(k), [&] {
      X12 x;
      double factor;
      if (f.float32) {  // draws the hinge first
        x = random_placement(r, random_well_shaped(r));
        factor = std::ldexp(r.uniform(1, 2), k);
      } else {
        factor = std::ldexp(r.uniform(1, 2), k);
        x = random_placement(r, random_well_shaped(r));
      }
      return f.round(times(x, factor));
    });
  }
}

void offsets(Builder& b) {
  const Format& f = b.format();
  Random r(f.seed + 4);
  b.start("offsets");
  for (int k = 1; k <= f.offset_tens; ++k)
    for (int i = 0; i < f.per_offset_ten; ++i)
      b.add_drawn("1e" + std::to_string(k), [&] { return offset_hinge(r, f, power_of_ten(k)); });
  for (int k : f.offset_twos)  // all three coordinates offset by the same power of two
    b.add_drawn("2^" + std::to_string(k), [&] {
      const double o = std::ldexp(1.0, k);
      Local l;
      Rotation R;
      if (f.float32) {  // draws the rotation first
        R = random_rotation(r);
        l = random_well_shaped(r);
      } else {
        l = random_well_shaped(r);
        R = random_rotation(r);
      }
      return f.round(place(l.points(), {0.5, 0, 0}, R, 1, {o, -o, o}));
    });
  for (int i = 0; i < f.random_offsets; ++i) {
    const int k = r.integer(0, f.random_offset_to);
    b.add_drawn("random-1e" + std::to_string(k), [&] {
      const double m = r.uniform(1, 10) * power_of_ten(k);
      return offset_hinge(r, f, m);
    });
  }
}

void near_flat(Builder& b) {
  const Format& f = b.format();
  Random r(f.seed + 5);
  b.start("near-flat");
  for (int k : f.small_exponents)
    for (double side : {1.0, -1.0})
      b.add_drawn(signed_tag(side, "1e-" + std::to_string(k)),
                  [&] { return near_flat_hinge(r, f, random_well_shaped(r), k, side, false); });
  Local flat;  // theta = 0 exactly
  flat.u0 = 0.375, flat.h0 = 1, flat.u3 = 0.75, flat.h3 = 0.5;
  b.add("exact-axes", place(flat.points(), {0, 0, 0}, identity, 1, {0, 0, 0}));
  b.add("exact-axes-offset", place(flat.points(), {0, 0, 0}, {0, 0, 1, 1, 0, 0, 0, 1, 0}, 1, {1024, -3, 0.5}));
  b.add("exact-lattice", lattice_hinge(false));
  X12 scaled = lattice_hinge(false);
  for (double& v : scaled) v = std::ldexp(v, -20) + 0.25;  // at most 20 significant bits: floats
  b.add("exact-lattice-scaled", scaled);
}

void near_folded(Builder& b) {
  const Format& f = b.format();
  Random r(f.seed + 6);
  b.start("near-folded");
  for (int k : f.small_exponents)
    for (double side : {1.0, -1.0})
      b.add_drawn(signed_tag(side, "(pi-1e-" + std::to_string(k) + ")"),
                  [&] { return near_folded_hinge(r, f, random_foldable(r), k, side, false); });
  Local fold;
  fold.u0 = 0.375, fold.h0 = 1, fold.u3 = 0.75, fold.h3 = 0.5;
  fold.sin_psi = 0, fold.cos_psi = -1;  // theta = +pi exactly (the branch cut)
  b.add("exact-axes", place(fold.points(), {0, 0, 0}, identity, 1, {0, 0, 0}));
  b.add("exact-lattice", lattice_hinge(true));
  X12 scaled = lattice_hinge(true);
  for (double& v : scaled) v = std::ldexp(v, f.folded_lattice_exponent) - 7;
  b.add("exact-lattice-scaled", scaled);
}

void needles(Builder& b) {
  const Format& f = b.format();
  Random r(f.seed + 7);
  b.start("needles");
  for (int kind = 0; kind < 5; ++kind)  // every kind but cap-spike
    for (int k = 2; k <= 12; k += 2)
      b.add_drawn(std::string(needle_kinds[kind]) + "-1e-" + std::to_string(k),
                  [&] { return random_needle(r, f, needle_kinds[kind], k); });
}

void short_hinge_edges(Builder& b) {
  const Format& f = b.format();
  Random r(f.seed + 8);
  b.start("short-hinge-edges");
  if (f.float32) {  // |e0| = 2^-k u, k = 2 ... 60
    for (int k = 2; k <= 60; k += 2) b.add_drawn("2^-" + std::to_string(k), [&] { return short_hinge_edge(r, f, k); });
    return;
  }
  for (int k = 1; k <= 12; ++k)  // |e0| = 10^-k u, twice each, x0 and x3 at distance about 1
    for (int i = 0; i < 2; ++i)
      b.add_drawn("1e-" + std::to_string(k), [&] {
        Local l = random_well_shaped(r);
        l.L0 = power_of_ten(-k) * r.uniform(1, 2);
        l.u0 = l.L0 * r.uniform(-1, 2), l.u3 = l.L0 * r.uniform(-1, 2);
        return random_placement(r, l);
      });
  for (int k : {10, 20, 30, 40, 50, 60}) {  // |e0| = 2^-k exactly
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
      b.add(m.name + "-hinge" + std::to_string(h), b.format().round(hinge_coordinates(m.deformed, t.hinges[h])));
  }
}

std::vector<Case> quick_set(const Format& f) {
  std::vector<Case> cases;
  Builder b(cases, f);
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

// --- the hard families (hard_cases, hard_cases_float32) -----------------------------------------------

// per_family draws of each family, family after family from one generator; a draw that breaks the format's
// rule (a needle whose apex rounds onto the hinge edge, say) is dropped. Ids "family/N-tag", N counting the
// cases kept. Some draws come in another order in the float32 families (`f.float32`).
std::vector<Case> hard_set(const Format& f, std::uint64_t seed, int per_family) {
  std::vector<Case> out;
  Random r(seed);
  auto add = [&](const std::string& family, const std::string& tag, const X12& x) {
    if (f.valid(x)) out.push_back({family + "/" + std::to_string(out.size()) + "-" + tag, family, x, std::nullopt});
  };
  struct Needle {
    std::string tag;
    int k;
    X12 x;
  };
  // A needle of a random kind at 10^-k, k = 2 ... k_to (float32: the kind and k first).
  auto random_kind_needle = [&](int k_to) {
    if (f.float32) {
      const std::string kind = needle_kinds[static_cast<std::size_t>(r.integer(0, 5))];
      const int k = r.integer(2, k_to);
      return Needle{kind + "-1e-" + std::to_string(k), k, random_needle(r, f, kind, k)};
    }
    const Local l = random_well_shaped(r);
    const int k = r.integer(2, k_to);
    const double small = power_of_ten(-k) * r.uniform(1, 2);
    const std::string kind = needle_kinds[static_cast<std::size_t>(r.integer(0, 5))];
    return Needle{kind + "-1e-" + std::to_string(k), k, needle(r, f, l, kind, k, small)};
  };
  // A local hinge from make() and a random side (float32: the side first).
  auto with_side = [&](Local (*make)(Random&)) {
    std::pair<Local, double> p;
    if (f.float32) {
      p.second = r.sign();
      p.first = make(r);
    } else {
      p.first = make(r);
      p.second = r.sign();
    }
    return p;
  };

  for (int i = 0; i < per_family; ++i) {  // caps of 10^-k, spikes of 10^k
    const Needle n = random_kind_needle(f.needles_to);
    add("needles", n.tag, n.x);
  }
  for (int i = 0; i < per_family; ++i) {  // hinge edges from 2^-1 to 2^-60 of the others
    const int k = r.integer(1, 60);
    add("short-hinge-edges", "2^-" + std::to_string(k), short_hinge_edge(r, f, k));
  }
  for (int i = 0; i < per_family; ++i) {  // |theta| = 10^-k u
    const int k = r.integer(1, f.angles_to);
    const auto [l, side] = with_side(random_well_shaped);
    add("near-flat", "1e-" + std::to_string(k), near_flat_hinge(r, f, l, k, side, true));
  }
  for (int i = 0; i < per_family; ++i) {  // |theta| = pi - 10^-k u
    const int k = r.integer(1, f.angles_to);
    const auto [l, side] = with_side(random_foldable);
    add("near-folded", "pi-1e-" + std::to_string(k), near_folded_hinge(r, f, l, k, side, true));
  }
  for (int i = 0; i < per_family; ++i) {  // exactly folded (theta = +pi) or flat, on lattice planes, scaled
    X12 x = lattice_hinge(i % 2 == 0);
    const int k = r.integer(-f.folded_scale, f.folded_scale);
    const double o = std::ldexp(static_cast<double>(r.integer(-64, 64)), k);
    for (double& v : x) v = std::ldexp(v, k) + o;  // float32: at most 8 significant bits, floats
    add("folded", std::string(i % 2 == 0 ? "folded" : "flat") + "-2^" + std::to_string(k), x);
  }
  for (int i = 0; i < per_family; ++i) {  // offset 10^k u times the hinge's size
    const int k = r.integer(0, f.offsets_to);
    if (f.float32) {  // draws the magnitude first
      const double m = power_of_ten(k) * r.uniform(1, 10);
      add("offsets", "1e" + std::to_string(k), offset_hinge(r, f, m));
      continue;
    }
    const Local l = random_well_shaped(r);
    const P3 d = random_point(r, 1);
    const double m = power_of_ten(k) * r.uniform(1, 10);
    add("offsets", "1e" + std::to_string(k), translated(r, l, m, d));
  }
  for (int i = 0; i < per_family; ++i) {  // scaled by 2^k
    const int k = r.integer(-f.scales_to, f.scales_to);
    add("scales", "2^" + std::to_string(k),
        scaled_by_power_of_two(f.round(random_placement(r, random_well_shaped(r))), k));
  }
  for (int i = 0; i < per_family; ++i) {  // a needle, offset by 10^j in a random direction, rounded, scaled
    const Needle n = random_kind_needle(f.combined_needles_to);
    // float32: j <= 5 - k, so that rounding moves a cap of 10^-k by under 1e-2 of it
    const int j = r.integer(0, f.float32 ? 5 - n.k : 8);
    const double o = power_of_ten(j);
    const P3 d = random_point(r, 1);
    const int e = r.integer(-f.combined_scale, f.combined_scale);
    X12 x = n.x;
    for (int v = 0; v < 4; ++v)
      for (int c = 0; c < 3; ++c) x[3 * v + c] += o * d[c];
    add("combined", n.tag + "-offset-1e" + std::to_string(j) + "-2^" + std::to_string(e),
        scaled_by_power_of_two(f.round(x), e));
  }
  return out;
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

const std::vector<std::string>& categories() {
  static const std::vector<std::string> names{"well-shaped", "rotations",         "scales",
                                              "offsets",     "near-flat",         "near-folded",
                                              "needles",     "short-hinge-edges", "boundary-meshes"};
  return names;
}

std::vector<Case> inputs() { return quick_set(float64_format); }

std::vector<Case> float32_inputs() { return quick_set(float32_format); }

const std::vector<std::string>& hard_families() {
  static const std::vector<std::string> names{"needles", "short-hinge-edges", "near-flat", "near-folded",
                                              "folded",  "offsets",           "scales",    "combined"};
  return names;
}

std::vector<Case> hard_cases(std::uint64_t seed, int per_family) { return hard_set(float64_format, seed, per_family); }

std::vector<Case> hard_cases_float32(std::uint64_t seed, int per_family) {
  return hard_set(float32_format, seed, per_family);
}

std::vector<Case> deep_inputs() { return deep_ids(hard_cases(deep_seed, deep_per_family)); }

std::vector<Case> deep_float32_inputs() { return deep_ids(hard_cases_float32(deep_seed, deep_per_family)); }

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
