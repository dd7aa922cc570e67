"""hinge: discrete bending forces and their Jacobians (Tamstorf & Grinspun 2013) from Python.

The hinge angle theta, its gradient and Hessian, hinge by hinge (``eval``, ``oracle``) and the bending
energy of a whole mesh (``hessian``), computed by the C++ library: every value is bit for bit what the
``hinge`` command prints for the same method and scalar type. The GIL is released while they compute.
Variables of a hinge: x0, x1, x2, x3, 12 coordinates (docs/contract.md, "The hinge stencil").
docs/python.md has a worked example.
"""

from . import _hinge
from .conformance import conform, conform_energy
from .mesh_conformance import conform_mesh
from .study import study

Result = _hinge.Result

__all__ = ["eval", "oracle", "hessian", "conform", "conform_energy", "conform_mesh", "study", "Result"]


def eval(x, method="fast", scalar="double", faithful=False):  # noqa: A001 (the contract's name)
    """theta, grad theta and Hess theta of hinges, by a method in a scalar type, rounded to double.

    x: array-like of shape (n, 12) (or (12,), taken as (1, 12)), any dtype convertible to float64: per
    hinge x0.x, x0.y, x0.z, x1.x, ..., x3.z.
    method: "reference", "fast", "autodiff" or "symbolic".
    scalar: "float", "double", "long-double", "dd", "qd", "float128", "bin128" or "mpfr:BITS".
    faithful: with method "fast" and scalar "double", the faithful mode: every output group within 1 unit
    of 2^-53 of the exact values, normwise (``hinge eval --method fast --faithful``; 2.2 to 2.8 times the
    plain kernel's time).

    Returns a Result: theta (n,), grad (n, 12), hess (n, 12, 12) as float64 arrays, and error, a list of
    n entries, None or the reason the hinge could not be evaluated (a degenerate hinge, a result outside
    the range of double); such a hinge's rows are NaN. Bit for bit ``hinge eval --method M --scalar S``
    (and ``--faithful``). Raises ValueError for a bad argument (shape, dtype, unknown method or scalar,
    faithful with another method or scalar).
    """
    return _hinge.eval(x, method, scalar, faithful)


def oracle(x):
    """The certified values: every output the double nearest to the exact value for the input doubles.

    x as for eval. Returns a Result as eval does (bit for bit ``hinge oracle``), with also uncertified:
    per hinge None, or the outputs the oracle could not certify within its precision cap (printed as the
    double nearest to their enclosure's midpoint; in practice never).
    """
    return _hinge.oracle(x)


def hessian(vertices, faces, rest=None, energy="tan", k=1.0, method="fast", threads=0, scalar="double",
            allow_no_hinges=False):
    """The bending energy of a mesh, its gradient and its Hessian.

    vertices: (n, 3) float64-convertible; faces: (m, 3) integers, 0-based, counter-clockwise;
    rest: the rest shape, (n, 3), same faces (default: vertices); energy: "tan", "shells" (also
    "willmore", "bridson"; docs/quantities.md) with stiffness k; method and scalar as for eval; threads:
    0 for all cores (never changes an output bit). A mesh without an interior edge is an error unless
    allow_no_hinges.

    Returns (energy, gradient (3n,), H), H a scipy.sparse.csr_matrix holding the full symmetric 3n x 3n
    Hessian, global index 3 v + c: the same numbers as ``hinge hessian --out`` (which stores the lower
    triangle). Raises ValueError for bad arguments or an invalid mesh (the message names the face or
    edge), OverflowError for a result outside the range of double.
    """
    return _hinge.hessian(vertices, faces, rest, energy, k, method, threads, scalar, allow_no_hinges)
