"""The demo's Python part (scripts/demo.sh): a small NumPy bending kernel as simulators write them, its
hinge listed (opposite vertex, other opposite vertex, edge start, edge end) and its angle positive for a
valley, checked with hinge.conform without declaring either: the report fails and its diagnosis says
what to change (docs/python-conformance.md)."""

import numpy as np

import hinge


def bend_angle_and_gradient(X):
    """theta and d theta / dx of hinges (n, 12) given as rows (a, b, e1, e2): a and b the vertices
    opposite the edge e1 -> e2."""
    a, b, e1, e2 = X[:, 0:3], X[:, 3:6], X[:, 6:9], X[:, 9:12]
    e = e2 - e1
    na = np.cross(e1 - a, e2 - a)  # the triangle (a, e1, e2)
    nb = np.cross(e2 - b, e1 - b)  # the triangle (b, e2, e1)
    length = np.linalg.norm(e, axis=1)
    sin = np.einsum("ij,ij->i", np.cross(na, nb), e) / length
    theta = -np.arctan2(sin, np.einsum("ij,ij->i", na, nb))  # positive for a valley
    ga = length[:, None] * na / np.einsum("ij,ij->i", na, na)[:, None]
    gb = length[:, None] * nb / np.einsum("ij,ij->i", nb, nb)[:, None]
    dot = lambda u, v: np.einsum("ij,ij->i", u, v)[:, None] / (length**2)[:, None]  # noqa: E731
    g1 = dot(a - e2, e) * ga + dot(b - e2, e) * gb
    g2 = -dot(a - e1, e) * ga - dot(b - e1, e) * gb
    return theta, np.concatenate([ga, gb, g1, g2], axis=1)


with np.errstate(all="ignore"):  # NumPy's warnings on the scales category's overflows: the report counts them
    report = hinge.conform(bend_angle_and_gradient, outputs=("theta", "grad"))
print(report)
