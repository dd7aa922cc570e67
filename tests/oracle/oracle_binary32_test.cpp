// The certified oracle rounding to binary32 (hinge/oracle/oracle.hpp, Options::binary32): every output the
// float nearest to the exact value. Checked against the certified doubles: rounding the double to float
// gives the same float except where the double is itself a midpoint between two floats (then, and only
// then, double rounding can be off, and a constructed case shows it is); ties, the decision in integers of
// an enclosure straddling a float midpoint, the branch cut, the normal range of float, the conditioning.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "hinge/conformance/inputs.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/conditioning.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge/reference/evaluate.hpp"

namespace hinge::oracle {
namespace {

using X12 = std::array<double, 12>;

Options binary32() {
  Options o;
  o.binary32 = true;
  return o;
}

std::vector<double> outputs(const CertifiedTheta& c) {
  std::vector<double> v{c.theta};
  v.insert(v.end(), c.grad.begin(), c.grad.end());
  v.insert(v.end(), c.hess.begin(), c.hess.end());
  return v;
}

// Whether the double d is exactly halfway between two floats (within float's normal range): d - float(d)
// is then half the gap between float(d) and its neighbour on d's side.
bool is_float_midpoint(double d) {
  const float f = static_cast<float>(d);
  if (static_cast<double>(f) == d || !std::isfinite(f)) return false;
  const float toward = std::nextafter(f, d > f ? INFINITY : -INFINITY);
  return 2 * (d - static_cast<double>(f)) == static_cast<double>(toward) - static_cast<double>(f);
}

bool is_float(double d) { return static_cast<double>(static_cast<float>(d)) == d; }

// The property on one hinge: the binary32 outputs are floats, and equal the certified doubles rounded to
// float wherever those doubles are not float midpoints (rounding to nearest is monotone, and every float
// midpoint is a double: one strictly between the exact value and its nearest double would be nearer).
// Returns how many outputs were double midpoints (not compared).
int expect_double_rounded_unless_midpoint(const X12& x, const std::string& what) {
  const std::vector<double> d = outputs(certified_theta_derivatives(x));
  const CertifiedTheta c32 = certified_theta_derivatives(x, binary32());
  EXPECT_NE(c32.path, Path::fast) << what;  // the fast path decides roundings to double only
  const std::vector<double> f = outputs(c32);
  int midpoints = 0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    EXPECT_TRUE(is_float(f[k])) << what << " output " << k;
    if (is_float_midpoint(d[k])) {
      ++midpoints;
      continue;
    }
    EXPECT_EQ(f[k], static_cast<double>(static_cast<float>(d[k]))) << what << " output " << k;
  }
  return midpoints;
}

TEST(OracleBinary32, IsTheCertifiedDoubleRoundedToFloatUnlessThatDoubleIsAFloatMidpoint) {
  // Well-shaped hinges (offset up to 100: coordinates of several magnitudes) and hinges in [-1, 1]^12.
  int midpoints = 0, hinges = 0;
  for (const X12& x : reference::well_shaped_hinges(400, 32)) {
    midpoints += expect_double_rounded_unless_midpoint(x, "well-shaped hinge " + std::to_string(hinges));
    ++hinges;
  }
  std::mt19937_64 random(2024);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  for (int i = 0; i < 400; ++i) {
    X12 x;
    for (double& v : x) v = coordinate(random);
    try {
      exact_hinge(x, false);
    } catch (const InputError&) {
      continue;  // degenerate (never, in practice)
    }
    midpoints += expect_double_rounded_unless_midpoint(x, "random hinge " + std::to_string(i));
    ++hinges;
  }
  EXPECT_GE(hinges, 790);
  // A double midpoint needs the exact value within 2^-53 (relative) of a float midpoint: about one output in
  // 2^29, so none is expected here.
  EXPECT_EQ(midpoints, 0);
}

TEST(OracleBinary32, RoundingTheCertifiedDoubleToFloatIsSometimesWrong) {
  // A flat hinge with both heights 1: grad_x1.z = 2 - a - c exactly. With a = 1/2 - 2^-25 and c = a - 2^-54
  // it is 1 + 2^-24 + 2^-54, just above the midpoint 1 + 2^-24 of the floats 1 and 1 + 2^-23: the certified
  // double is that midpoint (2^-54 is a quarter of an ulp of double), which rounds to the even float 1;
  // the certified float is 1 + 2^-23.
  const double a = 0.5 - 0x1p-25, c = a - 0x1p-54;
  const X12 x{a, 1, 0, 0, 0, 0, 1, 0, 0, c, -1, 0};
  const double d = certified_theta_derivatives(x).grad[5];
  EXPECT_EQ(d, 1 + 0x1p-24);
  EXPECT_TRUE(is_float_midpoint(d));
  EXPECT_EQ(static_cast<float>(d), 1.0f);
  EXPECT_EQ(certified_theta_derivatives(x, binary32()).grad[5], 1 + 0x1p-23);
}

TEST(OracleBinary32, DecidesAnEnclosureStraddlingAFloatMidpointInIntegers) {
  // The hinge above at 53 bits: the enclosure of grad_x1.z is a few units of 2^-52 wide around
  // 1 + 2^-24 + 2^-54 and contains the float midpoint 1 + 2^-24; the exact comparison decides at once.
  const double a = 0.5 - 0x1p-25, c = a - 0x1p-54;
  const X12 x{a, 1, 0, 0, 0, 0, 1, 0, 0, c, -1, 0};
  Options low = binary32();
  low.start_bits = 53;
  const CertifiedTheta r = certified_theta_derivatives(x, low);
  EXPECT_EQ(r.grad[5], 1 + 0x1p-23);
  EXPECT_GT(r.decided_exactly, 0u);
  EXPECT_EQ(r.bits, 53u);
  EXPECT_TRUE(r.uncertified.empty());
}

TEST(OracleBinary32, TiesAreDetectedAndRoundedToEven) {
  // a = c = 1/2 - 2^-25: grad_x1.z = 1 + 2^-24 exactly, halfway between the floats 1 and 1 + 2^-23.
  const double a = 0.5 - 0x1p-25;
  const X12 x{a, 1, 0, 0, 0, 0, 1, 0, 0, a, -1, 0};
  for (unsigned start : {53u, 128u}) {  // an enclosure straddling the tie, and a point enclosure
    Options o = binary32();
    o.start_bits = start;
    const CertifiedTheta r = certified_theta_derivatives(x, o);
    EXPECT_EQ(r.grad[5], 1.0) << start;
    EXPECT_GE(r.ties, 1u) << start;
    EXPECT_TRUE(r.uncertified.empty()) << start;
  }
  // a = c = 1/2 - 3 2^-25: 1 + 3 2^-24, halfway between 1 + 2^-23 (odd) and 1 + 2^-22 (even).
  const double b = 0.5 - 3 * 0x1p-25;
  EXPECT_EQ(certified_theta_derivatives({b, 1, 0, 0, 0, 0, 1, 0, 0, b, -1, 0}, binary32()).grad[5], 1 + 0x1p-22);
}

TEST(OracleBinary32, TheBranchCutIsPiRoundedToFloatAndExactZerosStayZero) {
  mpfr_t pi;
  mpfr_init2(pi, 24);
  mpfr_const_pi(pi, MPFR_RNDN);
  const double pi_float = mpfr_get_d(pi, MPFR_RNDN);
  mpfr_clear(pi);
  EXPECT_EQ(pi_float, static_cast<double>(3.14159274f));
  for (const X12& x : {X12{0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.25, 0.5, 0}, X12{7, 5, -4, 0, 0, 0, 3, 6, 6, 4, 5, 2}})
    EXPECT_EQ(certified_theta_derivatives(x, binary32()).theta, pi_float);
  const CertifiedTheta flat = certified_theta_derivatives({0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, -1, 0}, binary32());
  EXPECT_EQ(flat.theta, 0.0);
  EXPECT_EQ(flat.grad[0], 0.0);
  EXPECT_EQ(flat.grad[2], -1.0);
}

// Whether certifying x in binary32 throws "... outside the normal range of float".
bool outside_float(const X12& x) {
  try {
    certified_theta_derivatives(x, binary32());
    return false;
  } catch (const DomainError& e) {
    EXPECT_NE(std::string(e.what()).find("is outside the normal range of float"), std::string::npos) << e.what();
    return true;
  }
}

TEST(OracleBinary32, OutputsOutsideTheNormalRangeOfFloatAreErrors) {
  const X12 unit{0.5, 1, 0.25, 0, 0, 0, 1, 0, 0, 0.5, -1, 0.5};
  EXPECT_FALSE(outside_float(unit));
  for (int k : {-70, 70}) {  // the Hessian ~ 2^140 (overflows float), or ~ 2^-140 (below FLT_MIN)
    X12 x = unit;
    for (double& v : x) v = std::ldexp(v, k);
    EXPECT_TRUE(outside_float(x)) << k;
    EXPECT_NO_THROW(certified_theta_derivatives(x)) << k;  // all within double's range
  }
  EXPECT_TRUE(outside_float({0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, -1, 1e-40}));  // theta ~ 1e-40: below FLT_MIN
}

TEST(OracleBinary32, ThrowsExactlyWhereTheCertifiedDoublesLeaveTheNormalRangeOfFloat) {
  // On the conformance inputs (scales 2^-500 to 2^500, needles, subnormal-free near-flat hinges): an
  // output whose certified double is nonzero and below FLT_MIN by more than a relative 2^-24, or at least
  // 2^128, makes binary32 throw; every output zero or within [FLT_MIN, FLT_MAX] makes it succeed (outputs
  // within 2^-24 of those bounds are not judged: none here).
  int thrown = 0, certified = 0;
  for (const auto& c : conformance::inputs()) {
    bool below = false, above = false, unsure = false;
    for (double d : outputs(certified_theta_derivatives(c.x))) {
      const double m = std::fabs(d);
      if (m == 0) continue;
      if (m < FLT_MIN * (1 - 0x1p-24)) below = true;
      else if (m >= 0x1p128) above = true;
      else if (m < FLT_MIN || m > FLT_MAX) unsure = true;
    }
    if (unsure && !below && !above) continue;
    const bool out = outside_float(c.x);
    EXPECT_EQ(out, below || above) << c.id;
    (out ? thrown : certified) += 1;
  }
  EXPECT_GT(thrown, 0);
  EXPECT_GT(certified, 250);
}

TEST(OracleBinary32, ConditioningIsTheBinary64OnesWithFloatValues) {
  const X12 x{0.125, 0.75, -0.5, -0.25, 0.0625, 0.0, 1.0, 0.125, -0.0625, 0.625, -0.875, 0.375};
  const ConditionedTheta d = certified_with_conditioning(x), f = certified_with_conditioning(x, binary32());
  EXPECT_EQ(f.conditioning.length, d.conditioning.length);
  EXPECT_EQ(f.conditioning.scale, d.conditioning.scale);
  EXPECT_EQ(f.conditioning.kappa, d.conditioning.kappa);
  EXPECT_EQ(outputs(f.values), outputs(certified_theta_derivatives(x, binary32())));
}

}  // namespace
}  // namespace hinge::oracle
