// The certified oracle (hinge/oracle/oracle.hpp), three ways:
// - against an independent evaluation: the reference (another transcription of eqs. (4)-(6)) in MPFR at
//   1024 or 4096 bits, rounded to double, on every conformance input and on hard cases; equal bit for
//   bit wherever the reference's own error cannot matter;
// - exact identities of the exact stage, checked in integers: translation and rotation invariance of
//   the gradient, symmetry and translation invariance of the Hessian, |N|^2 |Nt|^2 = X^2 + Y^2 / s;
// - its certification logic: the contract's worked examples, exact zeros, the branch cut, ties, the
//   range of double, and flags at a precision cap.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "hinge/conformance/inputs.hpp"
#include "hinge/core/errors.hpp"
#include "hinge/oracle/oracle.hpp"
#include "hinge/reference/rounded.hpp"

namespace hinge::oracle {
namespace {

using X12 = std::array<double, 12>;

std::vector<nlohmann::json> read_lines(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot read " << path;
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

std::string show(const X12& x) {
  std::string s;
  char b[40];
  for (double v : x) {
    std::snprintf(b, sizeof b, "%.17g ", v);
    s += b;
  }
  return s;
}

// The 157 outputs of a certified result and of a rounded reference result, in one order.
std::vector<double> outputs(const CertifiedTheta& c) {
  std::vector<double> v{c.theta};
  v.insert(v.end(), c.grad.begin(), c.grad.end());
  v.insert(v.end(), c.hess.begin(), c.hess.end());
  return v;
}
std::vector<double> outputs(const RoundedTheta& r) {
  std::vector<double> v{r.theta};
  v.insert(v.end(), r.grad.begin(), r.grad.end());
  v.insert(v.end(), r.hess.begin(), r.hess.end());
  return v;
}

// Expects the oracle to equal the reference in MPFR at `bits`, rounded. Where the oracle's output is an
// exact zero the reference may hold rounding noise (it cannot decide zeros): then only |noise| <= 2^-(bits-64)
// times the largest output is asked.
void expect_agrees_with_reference(const X12& x, unsigned bits, const std::string& what) {
  const CertifiedTheta c = certified_theta_derivatives(x);
  EXPECT_TRUE(c.uncertified.empty()) << what;
  const auto r = reference::theta_derivatives_rounded({ScalarType::Kind::kind_mpfr, bits}, x);
  const std::vector<double> a = outputs(c), b = outputs(r);
  double largest = 0;
  for (double v : a) largest = std::max(largest, std::fabs(v));
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k] == 0) {
      EXPECT_LE(std::fabs(b[k]), std::ldexp(largest, -static_cast<int>(bits) + 64)) << what << " output " << k;
    } else {
      EXPECT_EQ(a[k], b[k]) << what << " output " << k << " (0 theta, 1-12 grad, 13-156 hess); x = " << show(x);
    }
  }
}

TEST(Oracle, ReproducesTheContractExamples) {
  const auto inputs = read_lines(HINGE_EXAMPLES_DIR "/eval-input.jsonl");
  const auto want = read_lines(HINGE_EXAMPLES_DIR "/oracle-output.jsonl");
  ASSERT_EQ(inputs.size(), 3u);
  ASSERT_EQ(want.size(), 3u);
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const CertifiedTheta c = certified_theta_derivatives(inputs[k]["x"].get<X12>());
    EXPECT_TRUE(c.uncertified.empty());
    EXPECT_EQ(c.theta, want[k]["theta"].get<double>()) << want[k]["id"];
    for (int i = 0; i < 12; ++i)
      EXPECT_EQ(c.grad[i], want[k]["grad"][i].get<double>()) << want[k]["id"] << " grad " << i;
    for (int i = 0; i < 144; ++i)
      EXPECT_EQ(c.hess[i], want[k]["hess"][i].get<double>()) << want[k]["id"] << " hess " << i;
  }
}

TEST(Oracle, AgreesWithTheReferenceAt1024BitsOnEveryConformanceInput) {
  for (const auto& c : conformance::inputs()) expect_agrees_with_reference(c.x, 1024, c.id);
}

TEST(Oracle, AgreesWithTheReferenceAt4096BitsOnHardCases) {
  const std::vector<std::pair<const char*, X12>> cases{
      // coordinates whose differences need about 1100 bits (1e-300 next to 1), subnormal outputs
      {"span", {0.5, 1, 1e-300, 0, 0, 0, 1, 0, 0, 0.5, -1, 5e-324}},
      {"span-subnormal", {0.5, 1, 1e-300, 0, 0, 1e-320, 1, 0, 0, 0.5, -1, 5e-324}},
      // outputs near the top and the bottom of the range of double
      {"huge", {0.5e300, 1e300, 0.25e300, 0, 0, 0, 1e300, 0, 0, 0.5e300, -1e300, 1e-300}},
      {"small", {0.5e-150, 1e-150, 0.25e-150, 0, 0, 0, 1e-150, 0, 0, 0.5e-150, -1e-150, 1e-160}},
      {"far", {1e15 + 0.5, 1, 0.25, 1e15, 0, 0, 1e15 + 1, 0, 0, 1e15 + 0.25, -1, 0.5}},
  };
  for (const auto& [name, x] : cases) expect_agrees_with_reference(x, 4096, name);
}

TEST(Oracle, DecidesOutputsCloserToAMidpointThanAnyPrecisionCap) {
  // Subnormal Hessian entries within about 2^-4250 (relative) of a midpoint between two subnormals: no
  // enclosure below that precision rounds to one double; the exact comparison with the midpoint decides
  // at the first precision. The reference needs 16384 bits to agree.
  const X12 x{1.5, 1, 5e-324, 1, 0, 0, 2, 0, 0, 1.5, -1, 1e-320};
  const CertifiedTheta c = certified_theta_derivatives(x);
  EXPECT_EQ(c.bits, Options{}.start_bits);
  EXPECT_GT(c.decided_exactly, 0u);
  expect_agrees_with_reference(x, 16384, "near-midpoint subnormals");
}

// Exact identities of the exact stage (exact.hpp), in integers.
TEST(Oracle, ExactStageSatisfiesTheInvariancesExactly) {
  for (const auto& c : conformance::inputs()) {
    const ScaledHinge s = scale_exactly(c.x);
    const ExactHinge e = exact_hinge(s, true);
    // |N x Nt|^2 = nn tt - X^2 and N x Nt is parallel to e0, so Y^2 = (nn tt - X^2) s.
    EXPECT_EQ(e.Y * e.Y, (e.nn * e.tt - e.X * e.X) * e.s) << c.id;
    for (int k = 0; k < 3; ++k) {
      // Translation invariance: the gradient sums to zero over the vertices ...
      EXPECT_EQ(e.g[k] + e.g[3 + k] + e.g[6 + k] + e.g[9 + k], 0) << c.id;
      // ... and so does every column of the Hessian.
      for (int j = 0; j < 12; ++j)
        EXPECT_EQ(e.h[12 * k + j] + e.h[12 * (3 + k) + j] + e.h[12 * (6 + k) + j] + e.h[12 * (9 + k) + j], 0)
            << c.id << " column " << j;
    }
    // Rotation invariance: sum_v x_v x grad_v = 0.
    Int torque[3] = {0, 0, 0};
    for (int v = 0; v < 4; ++v) {
      const Int* X = &s.X[3 * v];
      const Int* g = &e.g[3 * v];
      torque[0] += X[1] * g[2] - X[2] * g[1];
      torque[1] += X[2] * g[0] - X[0] * g[2];
      torque[2] += X[0] * g[1] - X[1] * g[0];
    }
    for (const Int& t : torque) EXPECT_EQ(t, 0) << c.id;
    // Symmetry, and the zero block H03 (eq. (6)).
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j) {
        EXPECT_EQ(e.h[12 * i + j], e.h[12 * j + i]) << c.id;
        if (i < 3 && j >= 9) {
          EXPECT_EQ(e.h[12 * i + j], 0) << c.id;
        }
      }
  }
}

TEST(Oracle, ExactZerosAndTheBranchCut) {
  // Flat in z = 0: theta = 0 exactly, every x and y derivative exactly zero.
  const CertifiedTheta flat = certified_theta_derivatives({0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, -1, 0});
  EXPECT_EQ(flat.theta, 0.0);
  EXPECT_EQ(flat.grad[0], 0.0);
  EXPECT_EQ(flat.grad[2], -1.0);  // -n / h0 (docs/contract.md check values)
  // Folded flat onto itself: theta = +pi, never -pi, on and off the coordinate planes.
  for (const X12& x : {X12{0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.25, 0.5, 0}, X12{7, 5, -4, 0, 0, 0, 3, 6, 6, 4, 5, 2}}) {
    const CertifiedTheta c = certified_theta_derivatives(x);
    EXPECT_EQ(c.theta, 3.141592653589793) << show(x);
  }
}

TEST(Oracle, TiesAreDetectedExactlyAndRoundedToEven) {
  // grad_x1.z = 2 - a - c with a = c = 1/2 - 2^-54: exactly 1 + 2^-53, halfway between 1 and 1 + 2^-52.
  const double a = 0.5 - 0x1p-54;
  const X12 x{a, 1, 0, 0, 0, 0, 1, 0, 0, a, -1, 0};
  Options low;
  low.start_bits = 53;  // too few bits for the exact integers: the enclosure straddles the midpoint
  const CertifiedTheta c = certified_theta_derivatives(x, low);
  EXPECT_EQ(c.grad[5], 1.0);
  EXPECT_GE(c.ties, 1u);
  EXPECT_TRUE(c.uncertified.empty());
  EXPECT_EQ(certified_theta_derivatives(x).grad[5], 1.0);  // the default start: a point enclosure
}

TEST(Oracle, OutputsOutsideTheRangeOfDoubleAreErrors) {
  // Hessian ~ 1 / length^2 = 2^2000
  const X12 tiny{0.5e-300, 1e-300, 0.25e-300, 0, 0, 0, 1e-300, 0, 0, 0.5e-300, -1e-300, 1e-310};
  EXPECT_THROW(certified_theta_derivatives(tiny), DomainError);
}

TEST(Oracle, DegenerateAndNonFiniteInputsAreTheReferencesErrors) {
  const std::vector<X12> bad{
      {0.5, 1, 0, 0, 0, 0, 0, 0, 0, 0.5, -1, 0},             // x1 == x2
      {0.5, 0, 0, 0, 0, 0, 1, 0, 0, 0.5, -1, 0},             // upper triangle collinear
      {0.5, 1, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0},                // lower triangle collinear
      {0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.5, -1, std::nan("")},  // not finite
  };
  for (const X12& x : bad) {
    std::string oracle_message, reference_message;
    try {
      certified_theta_derivatives(x);
    } catch (const InputError& e) {
      oracle_message = e.what();
    }
    try {
      reference::theta_derivatives_rounded({ScalarType::Kind::kind_double, 0}, x);
    } catch (const InputError& e) {
      reference_message = e.what();
    }
    EXPECT_FALSE(oracle_message.empty()) << show(x);
    EXPECT_EQ(oracle_message, reference_message) << show(x);
  }
}

TEST(Oracle, FlagsOutputsLeftOpenAtThePrecisionCap) {
  const X12 generic{0.125, 0.75, -0.5, -0.25, 0.0625, 0.0, 1.0, 0.125, -0.0625, 0.625, -0.875, 0.375};
  Options capped;
  capped.start_bits = capped.max_bits = 53;
  capped.fast_path = false;  // the enclosures' logic (the fast path decides this hinge: oracle_fast_path_test)
  const CertifiedTheta c = certified_theta_derivatives(generic, capped);
  const CertifiedTheta full = certified_theta_derivatives(generic);
  ASSERT_FALSE(c.uncertified.empty());
  EXPECT_TRUE(full.uncertified.empty());
  for (const Uncertified& u : c.uncertified) {
    // The enclosure contains the certified value, and the printed value is its midpoint's nearest double.
    const std::vector<double> all = outputs(full);
    int k = 0;
    if (u.output.rfind("grad[", 0) == 0) k = 1 + std::stoi(u.output.substr(5));
    else if (u.output.rfind("hess[", 0) == 0) k = 13 + std::stoi(u.output.substr(5));
    EXPECT_LE(std::stod(u.lower), all[k]) << u.output;
    EXPECT_GE(std::stod(u.upper), all[k]) << u.output;
    EXPECT_EQ(outputs(c)[k], u.nearest);
  }
}

TEST(Oracle, RecordsThePrecisionItNeeded) {
  Options enclosures;
  enclosures.fast_path = false;
  for (const auto& c : conformance::inputs()) {
    const CertifiedTheta r = certified_theta_derivatives(c.x, enclosures);
    if (r.path == Path::exact) continue;  // every output an exact zero or theta = 0: no enclosure needed
    EXPECT_GE(r.bits, Options{}.start_bits) << c.id;
    EXPECT_LE(r.bits, Options{}.max_bits) << c.id;
    EXPECT_GT(r.exact_bits, 0u) << c.id;
  }
}

}  // namespace
}  // namespace hinge::oracle
