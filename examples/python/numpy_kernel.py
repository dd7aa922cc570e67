import numpy as np

import hinge


def bend(x0, x1, x2, x3):
    """theta and its gradient (g0, g1, g2, g3) for n hinges given as four (n, 3) arrays of vertices."""
    dot = lambda a, b: np.sum(a * b, axis=1, keepdims=True)
    e0 = x2 - x1  # the hinge edge
    l = np.sqrt(dot(e0, e0))
    N = np.cross(x1 - x0, x2 - x0)  # upper triangle (x0, x1, x2)
    Nt = np.cross(x2 - x3, x1 - x3)  # lower triangle (x3, x2, x1)
    theta = np.arctan2(dot(np.cross(N, Nt), e0)[:, 0] / l[:, 0], dot(N, Nt)[:, 0])
    n, nt = N / dot(N, N), Nt / dot(Nt, Nt)  # N / |N|^2, Nt / |Nt|^2
    g0 = -l * n  # eq. (4): -n / h0, h0 = |N| / |e0| the altitude of x0
    g3 = -l * nt
    g1 = (dot(x0 - x2, x1 - x2) * n + dot(x3 - x2, x1 - x2) * nt) / l
    g2 = (dot(x0 - x1, e0) * n + dot(x3 - x1, e0) * nt) / l
    return theta, (g0, g1, g2, g3)


def vertices(X):
    return [X[:, 3 * i:3 * i + 3] for i in range(4)]


def fd_hessian(gradient, X, h):
    """The Jacobian of gradient(X) (n, 12) by central differences, step h (n, 1) per hinge."""
    H = np.empty((len(X), 12, 12), X.dtype)
    for j in range(12):
        dX = np.zeros_like(X)
        dX[:, j] = h[:, 0]
        H[:, :, j] = (gradient(X + dX) - gradient(X - dX)) / (2 * h)
    return H


def gradient(X):
    return np.hstack(bend(*vertices(X))[1])


def kernel(X):
    """theta (n,), grad (n, 12), hess (n, 12, 12) for X (n, 12): x0, x1, x2, x3 per row, in X's dtype."""
    with np.errstate(all="ignore"):  # extreme scales over- and underflow
        x0, x1, x2, x3 = vertices(X)
        theta, g = bend(x0, x1, x2, x3)
        # the textbook step of central differences: eps^(1/3) (6e-6 in double) times the edge length
        h = np.cbrt(np.finfo(X.dtype).eps) * np.linalg.norm(x2 - x1, axis=1, keepdims=True)
        return theta, np.hstack(g), fd_hessian(gradient, X, h)


report = hinge.conform(kernel)
print(report)
