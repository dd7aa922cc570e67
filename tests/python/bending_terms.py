"""Bending terms as simulators write them, for the energy conformance's tests: psi = k w f(theta, theta_bar) per
hinge from X and R, the rest angle and weight computed from R, theta and its derivatives from hinge.eval (the
layer above theta is what these terms get right or wrong). Each takes (X, R) of shape (n, 12), the contract's
vertex order, and returns (energy, grad, hess) as a simulator's kernel would."""

import numpy as np

import hinge


def edge_vectors(R):
    """The four vertices relative to x1 (exact differences), scaled by their largest coordinate: no square of
    a coordinate over- or underflows at any scale. Returns (V (n, 4, 3), scale (n,))."""
    V = R.reshape(-1, 4, 3)
    V = V - V[:, 1:2]
    scale = np.abs(V).max(axis=(1, 2))
    return V / scale[:, None, None], scale


def edge_length(R):
    V, scale = edge_vectors(R)
    return np.linalg.norm(V[:, 2] - V[:, 1], axis=1) * scale


def contract_weight(R):
    """w = 3 |e_bar|^2 / A_bar, A_bar the two rest triangles' areas (scale-free)."""
    V, _ = edge_vectors(R)  # x1 at the origin
    e = V[:, 2]
    n0 = np.cross(e, V[:, 0])  # the triangles' normals from the hinge edge: no long edge cancels a short one
    n3 = np.cross(e, V[:, 3])
    area = (np.linalg.norm(n0, axis=1) + np.linalg.norm(n3, axis=1)) / 2
    return 3 * np.einsum("ij,ij->i", e, e) / area


def _assemble(theta, d1, d2, gauss_newton):
    """psi' grad theta and psi'' grad theta grad theta^T (+ psi' Hess theta unless Gauss-Newton)."""
    g = d1[:, None] * theta.grad
    H = d2[:, None, None] * np.einsum("ni,nj->nij", theta.grad, theta.grad)
    if not gauss_newton:
        H = H + d1[:, None, None] * theta.hess
    return g, H


def tan_term(k=1.0, weight=contract_weight, gauss_newton=False):
    """psi = k w (2 tan(theta/2) - 2 tan(theta_bar/2))^2 (eq. 8)."""

    def term(X, R):
        t = hinge.eval(X)
        theta_bar = hinge.eval(R).theta
        c = k * weight(R)
        half = np.tan(t.theta / 2)
        d = 2 * half - 2 * np.tan(theta_bar / 2)
        dphi = 1 + half * half
        g, H = _assemble(t, 2 * c * d * dphi, 2 * c * (dphi * dphi + d * half * dphi), gauss_newton)
        return c * d * d, g, H

    return term


def shells_term(k=1.0, weight=contract_weight, rest_angle=lambda theta_bar: theta_bar):
    """psi = k w (theta - theta_bar)^2, theta_bar = rest_angle(theta of R)."""

    def term(X, R):
        t = hinge.eval(X)
        theta_bar = rest_angle(hinge.eval(R).theta)
        c = k * weight(R)
        d = t.theta - theta_bar
        g, H = _assemble(t, 2 * c * d, 2 * c, False)
        return c * d * d, g, H

    return term


def willmore_term(k=1.0, weight=contract_weight):
    """psi = k w sin^2(theta/2) (no rest angle)."""

    def term(X, R):
        t = hinge.eval(X)
        c = k * weight(R)
        g, H = _assemble(t, c * np.sin(t.theta) / 2, c * np.cos(t.theta) / 2, False)
        return c * np.sin(t.theta / 2) ** 2, g, H

    return term


def bridson_term(k=1.0, weight=contract_weight):
    """psi = A (cos(theta/2) - B theta), A = -2 k w, B = -sin(theta_bar/2) / 2 (docs/quantities.md); psi' =
    A (sin(theta_bar/2) - sin(theta/2)) / 2 as 2 cos((theta + theta_bar)/4) sin((theta_bar - theta)/4): no
    cancellation of the two sines where both angles are near +-pi."""

    def term(X, R):
        t = hinge.eval(X)
        theta_bar = hinge.eval(R).theta
        A = -2 * k * weight(R)
        B = -np.sin(theta_bar / 2) / 2
        d1 = A * np.cos((t.theta + theta_bar) / 4) * np.sin((theta_bar - t.theta) / 4)
        g, H = _assemble(t, d1, -A * np.cos(t.theta / 2) / 4, False)
        return A * (np.cos(t.theta / 2) - B * t.theta), g, H

    return term


def quadratic_term(k=1.0, constant=3.0):
    """The isometric bending of Bergou et al. 2006: psi = k (constant / A_bar) |sum_j K_j x_j|^2, K the rest
    hinge's cotangent weights (docs/quantities.md; constant 3 is the contract's, Bergou's Q_e is 3 / A_bar
    with a 1/2 in front of the quadratic form)."""

    def term(X, R):
        V, _ = edge_vectors(R)  # cotangents and the area ratio are scale-free
        e0, e1, e2 = V[:, 2] - V[:, 1], V[:, 0] - V[:, 2], V[:, 1] - V[:, 0]
        t1, t2 = V[:, 3] - V[:, 2], V[:, 1] - V[:, 3]
        N = np.linalg.norm(np.cross(e0, e1), axis=1)
        Nt = np.linalg.norm(np.cross(e0, t1), axis=1)
        dot = lambda a, b: np.einsum("ij,ij->i", a, b)  # noqa: E731
        cot1, cot2 = -dot(e0, e2) / N, -dot(e0, e1) / N
        cott1, cott2 = -dot(e0, t2) / Nt, -dot(e0, t1) / Nt
        K = np.stack([-(cot1 + cot2), cot2 + cott2, cot1 + cott1, -(cott1 + cott2)], axis=1)  # (n, 4)
        _, scale = edge_vectors(R)
        c = k * constant / ((N + Nt) / 2 * scale * scale)  # A_bar in R's units
        P = X.reshape(-1, 4, 3)
        s = np.einsum("nj,njc->nc", K, P - P[:, 1:2])  # sum K = 0: differences from x1 (exact)
        energy = c * dot(s, s)
        grad = (2 * c[:, None, None] * K[:, :, None] * s[:, None, :]).reshape(-1, 12)
        hess = np.einsum("n,ni,nj,ab->niajb", 2 * c, K, K, np.eye(3)).reshape(-1, 12, 12)
        return energy, grad, hess

    return term
