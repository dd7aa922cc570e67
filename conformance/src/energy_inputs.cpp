// The inputs of the conformance of bending energies (hinge/conformance/energy_inputs.hpp), built as the
// conformance inputs are (construction.hpp): a fixed seed, IEEE-754 basic operations, MPFR's sines.
#include "hinge/conformance/energy_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "construction.hpp"
#include "hinge/conformance/inputs.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/exact.hpp"
#include "hinge/oracle/oracle.hpp"

namespace hinge::conformance {
namespace {

using namespace construction;

bool valid(const X12& x) {
  try {
    oracle::exact_hinge(x, false);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// A rest hinge in the local frame with its edge length, areas and altitudes drawn independently: |e0| = L0 in
// [0.25, 4], the altitudes h0 and h3 in [0.2, 1.5] L0, the feet u0 and u3 in [-0.25, 1.25] L0 (obtuse
// triangles included).
Local random_rest_frame(Random& r) {
  Local l;
  l.L0 = r.uniform(0.25, 4);
  const double h0 = r.uniform(0.2, 1.5), h3 = r.uniform(0.2, 1.5);
  const double u0 = r.uniform(-0.25, 1.25), u3 = r.uniform(-0.25, 1.25);
  l.h0 = h0 * l.L0, l.h3 = h3 * l.L0, l.u0 = u0 * l.L0, l.u3 = u3 * l.L0;
  return l;
}

// Flat: psi = 0 puts all four points in the plane z = 0 of the local frame; a signed permutation of the axes
// and an offset keep one coordinate equal on all four exactly, so theta_bar = 0 exactly.
X12 flat_rest(Random& r) {
  const Local l = random_rest_frame(r);
  const Rotation axes = random_axes(r);
  const P3 offset = random_point(r, 1);
  return place(l.points(), {0, 0, 0}, axes, 1, offset);
}

// A rest hinge folded by psi about its edge: theta_bar = -psi (lifting x3 along n, as psi > 0 does, makes
// theta negative, as lifting x0 does).
X12 angled_rest(Random& r, double psi) {
  Local l = random_rest_frame(r);
  l.set_psi(psi);
  return random_placement(r, l);
}

X12 near_cut_rest(Random& r) {
  Local l = random_rest_frame(r);
  const double delta = r.uniform(1e-3, 0.05);
  const double side = r.sign();
  l.set_folded(delta, side);
  return random_placement(r, l);
}

// x with vertex v moved by `sign` times the hinge edge e0 = x2 - x1 (within its triangle's plane: its
// triangle's normal, hence theta, is unchanged in exact arithmetic; the oracle checks the doubles).
X12 sheared(X12 x, int v, double sign) {
  for (int c = 0; c < 3; ++c) x[3 * v + c] = x[3 * v + c] + sign * (x[6 + c] - x[3 + c]);
  return x;
}

// R with theta(R) == theta(x) exactly and another shape (energy_inputs.hpp).
// Every coordinate zero or a normal float (held in the double).
bool normal_floats(const X12& x) {
  for (const double v : x)
    if (v != static_cast<double>(static_cast<float>(v)) || (v != 0 && std::fabs(v) < 0x1p-126)) return false;
  return true;
}

X12 rest_angle_rest(Random& r, const X12& x, bool float32) {
  const oracle::ExactHinge target = oracle::exact_hinge(x, false);
  const int magnitude = r.integer(1, 2);  // one draw per statement: a fixed order on every compiler
  const int k = r.sign() > 0 ? magnitude : -magnitude;
  const Rotation axes = random_axes(r);
  for (const X12& candidate : {sheared(sheared(x, 0, 1), 3, -1), sheared(x, 0, 1), sheared(x, 3, -1), x}) {
    const X12 turned =
        place({P3{candidate[0], candidate[1], candidate[2]}, P3{candidate[3], candidate[4], candidate[5]},
               P3{candidate[6], candidate[7], candidate[8]}, P3{candidate[9], candidate[10], candidate[11]}},
              {0, 0, 0}, axes, 1, {0, 0, 0});  // exact: a signed permutation
    const X12 rest = scaled_by_power_of_two(turned, k);
    bool finite = true;
    for (double v : rest) finite = finite && std::isfinite(v) && (v == 0 || std::fabs(v) >= 0x1p-1000);
    if (finite && (!float32 || normal_floats(rest)) && valid(rest) &&
        oracle::same_angle(oracle::exact_hinge(rest, false), target))
      return rest;
  }
  throw std::logic_error("rest-angle: no exact construction");  // the last candidate is always exact
}

// The binary exponent of x's size: that of its largest coordinate difference.
int size_exponent(const X12& x) {
  double largest = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      for (int c = 0; c < 3; ++c) largest = std::max(largest, std::fabs(x[3 * a + c] - x[3 * b + c]));
  return std::ilogb(largest);
}

}  // namespace

RestShape rest_shape(const std::array<double, 12>& r) {
  double largest = 0;
  for (int v = 0; v < 4; ++v)
    for (int c = 0; c < 3; ++c) largest = std::max(largest, std::fabs(r[3 * v + c] - r[3 + c]));
  const auto sub = [&](int a, int b, int c) { return (r[3 * a + c] - r[3 * b + c]) / largest; };
  const auto norm3 = [](double a, double b, double c) { return std::sqrt(a * a + b * b + c * c); };
  const auto area = [&](int o, int a, int b) {  // |(x_a - x_o) x (x_b - x_o)| / 2, in units of largest^2
    const double u[3] = {sub(a, o, 0), sub(a, o, 1), sub(a, o, 2)}, v[3] = {sub(b, o, 0), sub(b, o, 1), sub(b, o, 2)};
    return norm3(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]) / 2;
  };
  return {norm3(sub(2, 1, 0), sub(2, 1, 1), sub(2, 1, 2)) * largest, area(1, 0, 2) * largest * largest,
          area(2, 3, 1) * largest * largest};
}

const std::vector<std::string>& rest_kinds() {
  static const std::vector<std::string> kinds{"flat", "obtuse", "negative", "near-cut", "at-rest", "rest-angle"};
  return kinds;
}

namespace {

// `per_category` deformed hinges of each of `cats` among `all`, each with a rest hinge of every kind, the rest
// hinges drawn from `seed`; with `float32`, every rest coordinate a normal float (the drawn ones rounded to float).
EnergyInputs pair_with_rest_hinges(const std::vector<Case>& all, const std::vector<std::string>& cats, int per_category,
                                   std::uint64_t seed, bool float32 = false) {
  EnergyInputs out;
  Random r(seed);
  for (const std::string& category : cats) {
    std::vector<const Case*> members;
    for (const Case& c : all)
      if (c.category == category) members.push_back(&c);
    const int n = static_cast<int>(members.size());
    const int count = std::min(per_category, n);
    std::vector<std::vector<EnergyCase>> by_kind(rest_kinds().size());
    for (int i = 0; i < count; ++i) {
      const Case& deformed = *members[static_cast<std::size_t>(i * n / count)];
      const std::string tag = deformed.id.substr(deformed.id.find('/') + 1);
      const double theta = oracle::certified_theta_derivatives(deformed.x).theta;
      for (std::size_t k = 0; k < rest_kinds().size(); ++k) {
        const std::string& kind = rest_kinds()[k];
        X12 rest;
        do {
          if (kind == "flat") rest = flat_rest(r);
          else if (kind == "obtuse") {
            const double magnitude = r.uniform(0.5 * pi + 0.05, pi - 0.05);
            rest = angled_rest(r, r.sign() * magnitude);
          } else if (kind == "negative") rest = angled_rest(r, r.uniform(0.05, 0.5 * pi));  // theta_bar = -psi
          else if (kind == "near-cut") rest = near_cut_rest(r);
          else if (kind == "at-rest") rest = deformed.x;
          else rest = rest_angle_rest(r, deformed.x, float32);
          // The drawn rest hinges (edges 0.25 to 4 long) brought to the deformed hinge's size by a power of two
          // (exact): a rest hinge 2^500 times larger than X would make the conditioning over X and R (L the
          // longest of their edges) overflow, and no simulator pairs such shapes. In float32 then rounded to
          // float: a flat rest hinge stays exactly flat (its four points share one coordinate, the offset's).
          if (kind != "at-rest" && kind != "rest-angle") {
            rest = scaled_by_power_of_two(rest, size_exponent(deformed.x));
            if (float32)
              for (double& v : rest) v = static_cast<double>(static_cast<float>(v));
          }
        } while (!valid(rest) || (float32 && !normal_floats(rest)));
        EnergyCase e{category + "/" + kind + "/" + tag, category + "/" + kind, deformed.x, rest};
        const double theta_bar = oracle::certified_theta_derivatives(rest).theta;
        if (std::fabs(theta - theta_bar) > pi) out.left_out.push_back(e.id);
        else by_kind[k].push_back(std::move(e));
      }
    }
    for (auto& cases : by_kind)
      for (EnergyCase& e : cases) out.cases.push_back(std::move(e));
  }
  return out;
}

}  // namespace

EnergyInputs energy_inputs(int per_category) {
  return pair_with_rest_hinges(inputs(), categories(), per_category, 0x5eede001);
}

EnergyInputs float32_energy_inputs(int per_category) {
  return pair_with_rest_hinges(float32_inputs(), categories(), per_category, 0x5eede032, true);
}

EnergyInputs deep_energy_inputs(int per_family) {
  return pair_with_rest_hinges(deep_inputs(), hard_families(), per_family, 0x5eede0d3);
}

}  // namespace hinge::conformance
