/* hinge/candidate.h: the C interface of an implementation checked by `hinge conform --plugin LIB.so`
 * (docs/contract.md, docs/conformance.md). Usable from C89 and C++.
 *
 *                 x0
 *               /  \          upper triangle (x0, x1, x2), hinge edge e0 = x2 - x1
 *             x1 -- x2        lower triangle (x3, x2, x1)
 *               \  /
 *                x3
 *
 * x:     the 12 coordinates x0.x, x0.y, x0.z, x1.x, ..., x3.z, each an exact double.
 * theta: the signed bend angle in (-pi, pi], with the sign of (N x Nt) . e0 (docs/contract.md).
 * grad:  d theta / dx, 12 numbers in the order of x.
 * hess:  d^2 theta / dx^2, 144 numbers, row-major.
 * Return 0 on success, nonzero when the hinge cannot be evaluated (counted as missing).
 *
 * A plugin exports one such function with C linkage, by default named hinge_candidate; another name is
 * given to hinge conform with --symbol NAME. It is called from one thread, once per conformance case.
 *
 * A bending term (`hinge conform --energy E --plugin LIB.so`; docs/energy-conformance-cli.md) is a second kind
 * of candidate, by default named hinge_energy_candidate: psi = k w f(theta, theta_bar) of one hinge.
 * x:      the deformed hinge, 12 coordinates in the order above, each an exact double.
 * rest:   its rest hinge, the same layout; the candidate computes its own weight w and rest angle theta_bar
 *         from it, as a simulator does.
 * energy: psi; grad: d psi / dx (12 numbers); hess: d^2 psi / dx^2 (144 numbers, row-major), the exact or
 *         the Gauss-Newton Hessian as declared with --hessian-kind.
 * Return 0 on success, nonzero when the pair cannot be evaluated (counted as missing). It is called from
 * one thread, once per graded pair and once per consistency probe.
 */
#ifndef HINGE_CANDIDATE_H
#define HINGE_CANDIDATE_H

#if defined(_WIN32)
#define HINGE_CANDIDATE_EXPORT __declspec(dllexport)
#else
#define HINGE_CANDIDATE_EXPORT __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* The type of a candidate function, whatever its name. */
typedef int hinge_candidate_fn(const double x[12], double* theta, double grad[12], double hess[144]);

/* The default symbol. */
HINGE_CANDIDATE_EXPORT int hinge_candidate(const double x[12], double* theta, double grad[12], double hess[144]);

/* The type of a bending-term candidate function, whatever its name. */
typedef int hinge_energy_candidate_fn(const double x[12], const double rest[12], double* energy, double grad[12],
                                      double hess[144]);

/* Its default symbol. */
HINGE_CANDIDATE_EXPORT int hinge_energy_candidate(const double x[12], const double rest[12], double* energy,
                                                  double grad[12], double hess[144]);

#ifdef __cplusplus
}
#endif

#endif /* HINGE_CANDIDATE_H */
