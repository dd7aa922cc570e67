"""A simulator's bending term, psi = 1/2 k |e_bar| (theta - theta_bar)^2, checked with hinge.conform_energy.

The contract's shells energy is psi = k w (theta - theta_bar)^2: this term is shells with the weight
w = |e_bar| / 2 (docs/energy-conformance.md, "Declaring your term"). theta and its derivatives come from
hinge.eval; the energy, its gradient and Hessian are the term's own (eqs. (2) and (3) for one hinge).
"""

import numpy as np

import hinge

K = 0.01  # the simulator's bending stiffness


def rest_edge_length(R):
    """|e_bar| = |x2 - x1| of each rest hinge (R: (n, 12), vertices x0, x1, x2, x3)."""
    return np.linalg.norm(R[:, 6:9] - R[:, 3:6], axis=1)


def bending_term(X, R):
    """Energy (n,), gradient (n, 12) and Hessian (n, 12, 12) of 1/2 K |e_bar| (theta - theta_bar)^2."""
    t = hinge.eval(X)  # theta, grad theta, Hess theta of the deformed hinges
    theta_bar = hinge.eval(R).theta  # the rest angles, from the rest hinges
    c = K * rest_edge_length(R)
    d = t.theta - theta_bar
    energy = 0.5 * c * d**2
    grad = (c * d)[:, None] * t.grad
    hess = c[:, None, None] * (np.einsum("ni,nj->nij", t.grad, t.grad) + d[:, None, None] * t.hess)
    return energy, grad, hess


def half_edge_length(R):
    """The term's weight in the contract's terms: psi = K w (theta - theta_bar)^2 with w = |e_bar| / 2."""
    return rest_edge_length(R) / 2


report = hinge.conform_energy(bending_term, energy="shells", k=K, weight=half_edge_length)
print(report)
