// hinge/oracle/oracle.hpp: the certified oracle for one hinge. Every output is the double nearest to the
// exact theta, grad theta (eq. (4)) and Hess theta (eqs. (5)-(6), errata applied) of the 12 input doubles
// taken as exact, with a proof:
//
// 0. fast path (oracle/src/fast_path.cpp, proofs/oracle-fast-path.md): the exact form of exact.hpp in
//    double-double arithmetic with a rigorous error bound on every quantity; an output whose whole
//    interval rounds to one double is decided (almost every output of an ordinary hinge), the others go
//    on to stages 1 and 2;
// 1. exact stage (exact.hpp): edges, normals, dot and cross products in integers; validity checks, the
//    sign of theta, and every exactly-zero output decided there, exactly;
// 2. certification (Ziv's strategy): each output is enclosed by MPFI at `start_bits`, and the precision
//    doubled until both end points of its enclosure round to the same double, up to `max_bits`. A
//    gradient or Hessian entry is the square root of a rational, so once its enclosure rounds to two
//    adjacent doubles, the side of their midpoint it lies on is decided exactly in integers (an exact
//    midpoint is rounded to even): these never reach the cap. theta is transcendental unless zero
//    (Lindemann), so it is never a tie; an output left undecided at `max_bits` (in practice only theta
//    within 2^-max_bits of a midpoint) is reported in `uncertified` with its enclosure, never silently
//    rounded.
//
// With Options::binary32 every output is instead the float nearest to the exact value (ties to even), held
// in the double fields: stages 1 and 2 only (the fast path decides roundings to double), the enclosures'
// end points rounded to 24 bits, and an entry whose enclosure rounds to two adjacent floats decided
// exactly against their midpoint (a double), as above. Rounding the certified double to float instead
// would be wrong exactly where that double is itself a midpoint between two floats (double rounding).
//
// Variables: x0, x1, x2, x3 (12); gradient 12, Hessian 144 row-major (docs/contract.md).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "hinge/oracle/exact.hpp"

namespace hinge::oracle {

struct Options {
  unsigned start_bits = 128;  // first working precision
  unsigned max_bits = 4096;   // the precision cap (documented in oracle/README.md)
  bool fast_path = true;      // try the double-double fast path first (certified_theta_derivatives)
  // Round to binary32 instead of binary64 (the header comment): a nonzero output below FLT_MIN = 2^-126 in
  // magnitude, or one that rounds above FLT_MAX, is a hinge::DomainError "<what> is outside the normal range
  // of float"; the branch cut is +pi rounded to float. fast_path is then ignored.
  bool binary32 = false;
  // certified_mesh only (mesh.hpp): the Hessian's Gauss-Newton part, sum over hinges of
  // psi'' grad theta grad theta^T (not clamped: psi'' may be negative), without psi' Hess theta.
  bool gauss_newton = false;
  // certified_mesh only: each hinge's weight w_i in place of the contract's a = 3 |e_bar|^2 / A_bar, taken as
  // the exact value of the double given (psi_i = k w_i f(theta, theta_bar); the conformance of named and
  // callable weights). Empty: the contract's weight. One per hinge of the topology; the fast path is skipped.
  std::vector<double> weights;
};

// Which stages a hinge's certification needed.
enum class Path {
  fast,      // the fast path decided every output
  exact,     // and the exact stage the rest (exact zeros: flat or axis-aligned hinges)
  interval,  // and MPFI enclosures (Ziv's strategy) some output
};
const char* path_name(Path p);  // "fast", "exact", "interval"

// An output the oracle could not certify within Options::max_bits.
struct Uncertified {
  std::string output;        // "theta", "grad[3]", "hess[17]"
  std::string lower, upper;  // the enclosure at the cap, in decimal, rounded outward
  double nearest = 0;        // the double nearest to the enclosure's midpoint (the value printed)
};

struct CertifiedTheta {
  double theta = 0;
  std::array<double, 12> grad{};
  std::array<double, 144> hess{};  // row-major
  Path path = Path::interval;
  unsigned bits = 0;             // largest working precision of the enclosures (0: none needed)
  std::size_t exact_bits = 0;    // size of the largest integer of the exact stage (0: not run)
  unsigned ties = 0;             // outputs exactly halfway between two values of the format (rounded to even)
  unsigned decided_exactly = 0;  // outputs whose enclosure straddled a midpoint, decided in integers
  std::vector<Uncertified> uncertified;
};

// Throws hinge::InputError (non-finite or degenerate input, the reference's messages) or
// hinge::DomainError (an exact output outside the range of double; with binary32, of normal floats).
// With options.fast_path (the default) the fast path (proofs/oracle-fast-path.md: eqs. (4)-(6) in
// double-double with a rigorous error bound) decides what it can, the exact stage and the enclosures the
// rest: the same doubles either way.
CertifiedTheta certified_theta_derivatives(const std::array<double, 12>& x, const Options& options = {});
// Stages 1 and 2 only (no fast path): path is `exact` or `interval`.
CertifiedTheta certify(const ExactHinge& exact, const Options& options = {});

}  // namespace hinge::oracle
