// Properties of the certified oracle's fast path (oracle/src/fast_path.cpp, proofs/oracle-fast-path.md):
// on any hinge the generators make (well-shaped, the hard families, exactly flat and folded, scales
// 2^-300 to 2^300) it gives the exact stage's and the enclosures' doubles bit for bit, and on an invalid
// hinge the same error. Runs in the sanitizer build too (label properties).
#include <cstring>

#include "hinge/oracle/oracle.hpp"
#include "property_support.hpp"

namespace hinge::test {
namespace {

oracle::Options enclosures_only() {
  oracle::Options o;
  o.fast_path = false;
  return o;
}

std::uint64_t bits(double v) {
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  return u;
}

// The first output where the two differ (-1: none); theta is output 0, grad 1..12, hess 13..156.
int first_difference(const oracle::CertifiedTheta& a, const oracle::CertifiedTheta& b) {
  if (bits(a.theta) != bits(b.theta)) return 0;
  for (int k = 0; k < 12; ++k)
    if (bits(a.grad[k]) != bits(b.grad[k])) return 1 + k;
  for (int k = 0; k < 144; ++k)
    if (bits(a.hess[k]) != bits(b.hess[k])) return 13 + k;
  return -1;
}

void gives_the_enclosures_doubles(const HingeCase& h) {
  oracle::CertifiedTheta slow, fast;
  std::string slow_error, fast_error;
  try {
    slow = oracle::certified_theta_derivatives(h.x, enclosures_only());
  } catch (const std::exception& e) {
    slow_error = e.what();
  }
  try {
    fast = oracle::certified_theta_derivatives(h.x);
  } catch (const std::exception& e) {
    fast_error = e.what();
  }
  RC_ASSERT(fast_error == slow_error);
  if (!slow_error.empty()) return;
  const int k = first_difference(fast, slow);
  if (k >= 0) {
    Report rep("oracle: the fast path gives the enclosures' doubles", h.x);
    rep.line("family " + h.family + " (" + h.recipe + "), path " + oracle::path_name(fast.path) + ", output " +
             std::to_string(k) + " differs");
    RC_FAIL(rep.finish(INFINITY, 0, "a decided output is the correctly rounded one"));
  }
}

RC_GTEST_PROP(OracleFastPath, GivesTheEnclosuresDoublesOnAnyHinge, ()) {
  gives_the_enclosures_doubles(*gen::any_hinge(wide_scales));
}

RC_GTEST_PROP(OracleFastPath, GivesTheEnclosuresDoublesOnFlatAndFoldedHinges, ()) {
  gives_the_enclosures_doubles(*gen::coplanar_hinge(*rc::gen::arbitrary<bool>()));
}

RC_GTEST_PROP(OracleFastPath, GivesTheSameErrorOnInvalidHinges, ()) { gives_the_enclosures_doubles(*gen::invalid_hinge()); }

}  // namespace
}  // namespace hinge::test
