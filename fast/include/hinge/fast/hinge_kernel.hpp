// hinge/fast/hinge_kernel.hpp: one hinge, lean: theta, grad theta (eq. (4)) and Hess theta (eqs. (5)-(6),
// with the errata of proofs/errata.md), templated on the scalar type and instantiated for float, double,
// long double, float128, bin128 and mpfr. How it computes them: src/generic_kernel.hpp (every type) and
// src/hinge_kernel_lanes.hpp (double, in eight lanes, compiled per instruction set: isa.hpp).
//
//                 x0                 upper triangle T = (x0, x1, x2), counter-clockwise about n
//          e1   /  \   e2            e_i = x_{i+2} - x_{i+1}: e0 = x2 - x1, e1 = x0 - x2, e2 = x1 - x0
//              / T  \                lower triangle T~ in the paper's labels (x3, x1, x2):
//            x1 ---> x2   e0         e~0 = e0, e~1 = x3 - x2, e~2 = x1 - x3, traversed clockwise about n~
//              \ T~ /                alpha_i angle at vertex i, h_i altitude from vertex i, m_i unit
//          e~2  \  /  e~1            outward normal of edge i (in the triangle's plane), l_i = |e_i|
//                x3
//
// Variables: x0, x1, x2, x3 (12); gradient 12, Hessian 12 x 12 (docs/contract.md).
//
// Accuracy (double; src/hinge_kernel_lanes.hpp): the coordinate differences are exact (two_diff), every
// dot and cross product is evaluated in double-double arithmetic (exact.hpp), both triangles and their
// edges side by side in eight lanes (lanes.hpp), and each of the per-triangle quantities above is rounded
// to double once; only then eq. (6) runs in double. Eq. (6) adds upper- and lower-triangle terms that
// nearly cancel on near-folded hinges, so few-unit errors in n, q, a would be amplified; rounded once
// they are not (measured on 20000 well-shaped hinges against MPFR at 256 bits: normwise median 1.07,
// worst 3.44 units of 2^-53; tests/fast/hinge_kernel_test.cpp asserts 2 and 4). theta comes from
// |n - n~|^2 and |n + n~|^2 summed in double-double (worst 2.4 units). Every product is formed from the
// edges directly, never from squared lengths (no law of cosines: e_2 . e_0 and e_0 . e_1 are dot
// products, C = e_2 x e_0 and e_0 x C are cross products with the hinge edge), so that a short hinge edge
// costs no digits beyond the problem's own condition. float computes the same quantities in double and
// rounds them to float; long double, float128, bin128 and mpfr compute them in their own format (worst
// about 10 units of their own precision on well-shaped hinges); those types use the generic kernel below.
//
// Range (double, float): the edges are brought by a power of two to a largest component M in [2^-200,
// 2^200] (left alone when they are there already, else to [1, 2); results scaled back exactly), and
// triangles() states for every intermediate the range it stays in when both triangles pass a shape
// check, made exactly invariant under power-of-two scaling: (2A)^2 >= 2^-140 M^4 (about: every altitude
// above 2^-72 times the longest edge) and l_0^2 >= 2^-500 M^2. Hinges beyond it (kappa_shape above
// ~2^70, or a hinge edge below ~2^-251 M: where the bound c kappa_shape u promises no digit anyway) go to
// wide_range_kernel: the same algorithm in long double, whose exponent range holds every intermediate of
// any hinge of doubles, with the normals' cross products computed exactly and rounded once, each result
// rounded to double once. So no valid input gives NaN or infinity unless the exact result overflows, and
// results are exactly invariant under power-of-two scaling (barring subnormal inputs or results, and
// products of edge components below ~2^-250 M, which may underflow at one scale and not at another).
//
// Validity, decided exactly on the input doubles as hinge::reference does (docs/contract.md): a non-finite
// coordinate, x1 == x2, or a triangle of exactly zero area is an InputError (same messages); the sign
// of theta comes from a floating-point filter, or from hinge_orientation_exact when the filter cannot
// decide, so that a hinge folded flat onto itself has theta = +pi.
#pragma once

#include <Eigen/Core>
#include <array>
#include <span>

#include "hinge/core/scalar.hpp"

namespace hinge::fast {

template <class Scalar>
struct HingeDerivatives {
  Scalar theta = 0;            // in (-pi, pi], docs/contract.md
  Scalar tan_half_theta = 0;   // eq. (12); +infinity on the branch cut
  bool on_branch_cut = false;  // folded flat onto itself: theta = +pi exactly
  Eigen::Matrix<Scalar, 12, 1> grad;
  Eigen::Matrix<Scalar, 12, 12> hess;  // left zero unless requested
};

// theta, grad theta and (if `want_hessian`) Hess theta of the hinge `x` (x0.x, x0.y, ..., x3.z).
// Throws hinge::InputError for a non-finite or degenerate hinge.
template <class Scalar>
HingeDerivatives<Scalar> hinge_derivatives(const std::array<double, 12>& x, bool want_hessian = true);
// The same for many hinges: out[i] for x[i], bit for bit what hinge_derivatives(x[i]) gives. For double
// with AVX-512, two hinges at a time (their chains of dependent operations overlapped).
// Throws std::invalid_argument if the two differ in size, and as hinge_derivatives for the first failing
// hinge in order (the other outputs are then unspecified).
template <class Scalar>
void hinge_derivatives(std::span<const std::array<double, 12>> x, std::span<HingeDerivatives<Scalar>> out,
                       bool want_hessian = true);

// The double kernel writing straight into the caller's arrays: theta, grad theta (12) and Hess theta (144,
// row-major; it is symmetric, so column-major too), bit for bit what hinge_derivatives<double>(x) gives,
// with no intermediate matrix copied out (the conformance plugin's path, hinge/candidate.h). Throws as
// hinge_derivatives does; the arrays' contents are then unspecified.
void hinge_derivatives_into(const std::array<double, 12>& x, double& theta, double* grad, double* hess);

#define HINGE_FAST_HINGE_EXTERN(S)                                                                                   \
  extern template HingeDerivatives<S> hinge_derivatives<S>(const std::array<double, 12>&, bool);                     \
  extern template void hinge_derivatives<S>(std::span<const std::array<double, 12>>, std::span<HingeDerivatives<S>>, \
                                            bool);
HINGE_FOR_EACH_SCALAR(HINGE_FAST_HINGE_EXTERN)
#undef HINGE_FAST_HINGE_EXTERN

}  // namespace hinge::fast
