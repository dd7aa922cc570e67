// hinge/core/predicates.hpp: exact geometric decisions on exact double inputs (docs/contract.md:
// "judged exactly on those doubles"). A floating-point filter decides almost every case; the rest fall
// back to exact rational arithmetic.
#pragma once

#include <array>

namespace hinge {

using Point = std::array<double, 3>;

// True when the triangle (a, b, c) has exactly zero area: (b - a) x (c - a) == 0 in exact arithmetic.
bool zero_area_exact(const Point& a, const Point& b, const Point& c);

// The exact sign (-1, 0, +1) of det[e0, x0 - x1, x1 - x3] with e0 = x2 - x1: the sign of theta
// (proofs/sign-convention.md); 0 on a flat or folded hinge.
int hinge_orientation_exact(const Point& x0, const Point& x1, const Point& x2, const Point& x3);

}  // namespace hinge
