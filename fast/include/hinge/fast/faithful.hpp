// hinge/fast/faithful.hpp: the double kernel's faithful mode (`hinge eval --method fast --faithful`): theta,
// grad theta and Hess theta of one hinge, each output group within 1 unit of 2^-53 of the exact values,
// normwise (||computed - exact||_2 <= 2^-53 ||exact||_2, the measure of docs/conformance.md). Measured,
// not proved: correctly rounded on every hard family of docs/hard-cases.md but for a few entries within
// 0.78 units, and on the conformance vectors; the error analysis (docs/numerics.md) holds for triangles of
// moderate shape, and on needles the double-double stencil's error grows with the shape's condition
// (about 2^-104 kappa_shape: the needles of the families, to 1e15, still measured within 0.3 units).
//
// How: the kernel of hinge_kernel.hpp computes every per-triangle quantity (n, q_j, a_j, r_0) in
// double-double from exact differences; the plain kernel rounds them to double and runs eqs. (4) and (6)
// in double (a few units of 2^-53), the faithful mode keeps them and runs eqs. (4) and (6) in double-double
// too, rounding each output once: the error before that rounding is a few units of 2^-100 times the
// outputs' own cancellation (at most the hinge's shape condition), so what remains is the rounding, at most
// 2^-53 of each entry. theta: faithful_theta.hpp. Cost: 2.2 to 2.8 times the plain kernel (bench/,
// hinge/faithful beside hinge/fast; docs/numerics.md). Range: the plain kernel's (kappa_shape below about 2^70, hinge
// edges above about 2^-251 of the longest edge, any scale); beyond it, the same long double fallback as the plain
// kernel, which is accurate to its own conditioning but not faithful.
//
// The same bits for every instruction set (isa.hpp); errors (InputError) as hinge_derivatives.
#pragma once

#include <array>

#include "hinge/core/rounding.hpp"
#include "hinge/fast/hinge_kernel.hpp"
#include "hinge/fast/isa.hpp"

namespace hinge::fast {

// theta, grad theta and (if `want_hessian`) Hess theta of the hinge x (x0.x, ..., x3.z), faithfully.
HingeDerivatives<double> faithful_hinge_derivatives(const std::array<double, 12>& x, bool want_hessian = true);
// The same in hinge::reference's result type (`hinge eval --faithful`, the Python module).
RoundedTheta faithful_derivatives_rounded(const std::array<double, 12>& x);
// The same compiled for `isa` (tests compare them): true, or false with nothing written where the
// processor lacks it.
bool faithful_hinge_derivatives(Isa isa, const std::array<double, 12>& x, bool want_hessian,
                                HingeDerivatives<double>& out);

}  // namespace hinge::fast
