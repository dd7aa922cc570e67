"""Shared helpers for the proofs/ checks: precision, small linear algebra on
lists of mpmath numbers, random hinge stencils aimed at the hard cases, and a
pass/fail report.  Nothing here knows the paper's formulas (paper_formulas.py)
or how theta is differentiated (theta_oracle.py).

Stencil layout (docs/contract.md): x = [x0.x, x0.y, x0.z, x1.x, ..., x3.z].

            x0
           /  \\        upper triangle T = (x0, x1, x2), counter-clockwise about n
         x1 ---- x2     hinge edge e0 = x2 - x1
           \\  /        lower triangle (x3, x2, x1) in mesh order, normal nt
            x3
"""
import argparse
import random
import sys

import mpmath
from mpmath import mp, mpf

PREC_BITS = 256


def setup(prec=PREC_BITS):
    mp.prec = prec


# ---------------------------------------------------------------- vectors
def vsub(u, v):
    return [u[0] - v[0], u[1] - v[1], u[2] - v[2]]


def vadd(u, v):
    return [u[0] + v[0], u[1] + v[1], u[2] + v[2]]


def vscale(s, u):
    return [s * u[0], s * u[1], s * u[2]]


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


def norm(u):
    return mpmath.sqrt(dot(u, u))


def unit(u):
    return vscale(1 / norm(u), u)


def det3(a, b, c):
    return dot(a, cross(b, c))


def pt(x, i):
    """Vertex i of a 12-vector stencil."""
    return [x[3 * i], x[3 * i + 1], x[3 * i + 2]]


def stencil(*pts):
    out = []
    for p in pts:
        out.extend(p)
    return out


# ---------------------------------------------------------------- matrices (lists of rows)
def zeros(r, c=None):
    c = r if c is None else c
    return [[mpf(0)] * c for _ in range(r)]


def outer(u, v):
    return [[ui * vj for vj in v] for ui in u]


def mT(A):
    return [list(r) for r in zip(*A)]


def madd(*As):
    out = [list(r) for r in As[0]]
    for A in As[1:]:
        for i, r in enumerate(A):
            for j, a in enumerate(r):
                out[i][j] += a
    return out


def mscale(s, A):
    return [[s * a for a in r] for r in A]


def msub(A, B):
    return madd(A, mscale(-1, B))


def matvec(A, v):
    return [sum((a * b for a, b in zip(r, v)), mpf(0)) for r in A]


def matmul(A, B):
    Bt = mT(B)
    return [[sum((a * b for a, b in zip(r, c)), mpf(0)) for c in Bt] for r in A]


def skew(u):
    """[u]_x, the matrix with [u]_x v = u x v."""
    return [[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]]


def block(H, i, j):
    """3x3 block (i, j) of a 12x12 matrix: rows are components of x_i."""
    return [H[3 * i + a][3 * j:3 * j + 3] for a in range(3)]


def from_blocks(B, nb=4):
    """12x12 (3nb x 3nb) matrix from a dict {(i, j): 3x3}; missing blocks are zero."""
    H = zeros(3 * nb)
    for (i, j), A in B.items():
        for a in range(3):
            for b in range(3):
                H[3 * i + a][3 * j + b] += A[a][b]
    return H


def fnorm(A):
    if A and isinstance(A[0], list):
        return mpmath.sqrt(sum(a * a for r in A for a in r))
    return mpmath.sqrt(sum(a * a for a in A))


def flat(A):
    if A and isinstance(A[0], list):
        return [a for r in A for a in r]
    return list(A)


def rel(A, B):
    """Normwise relative difference ||A - B|| / max(||A||, ||B||) (Frobenius)."""
    a, b = flat(A), flat(B)
    d = mpmath.sqrt(sum((p - q) ** 2 for p, q in zip(a, b)))
    s = max(fnorm(a), fnorm(b))
    return d / s if s != 0 else d


# ---------------------------------------------------------------- random stencils
def rand_rotation(rng):
    q = [mpf(rng.gauss(0, 1)) for _ in range(4)]
    s = mpmath.sqrt(sum(c * c for c in q))
    w, x, y, z = [c / s for c in q]
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def rotate_about(axis, ang, v):
    """Rodrigues rotation of v about unit axis by angle ang."""
    c, s = mpmath.cos(ang), mpmath.sin(ang)
    return vadd(vadd(vscale(c, v), vscale(s, cross(axis, v))), vscale((1 - c) * dot(axis, v), axis))


def make_hinge(l0, p0, h0, p3, h3, beta, R=None, scale=1, offset=(0, 0, 0)):
    """A hinge built from its intrinsic shape: hinge edge of length l0 on the x-axis,
    apex x0 at (p0, h0) in its half-plane, apex x3 at (p3, h3) in the other one,
    the lower half-plane turned by beta away from the flat position (beta = 0: flat,
    |theta| = |beta|), then rotated by R, scaled and translated."""
    ex = [mpf(1), mpf(0), mpf(0)]
    w0 = [mpf(0), mpf(1), mpf(0)]
    w3 = rotate_about(ex, mpf(beta), [mpf(0), mpf(-1), mpf(0)])
    x1 = [mpf(0)] * 3
    x2 = [mpf(l0), mpf(0), mpf(0)]
    x0 = vadd(vscale(mpf(p0), ex), vscale(mpf(h0), w0))
    x3 = vadd(vscale(mpf(p3), ex), vscale(mpf(h3), w3))
    pts = [x0, x1, x2, x3]
    if R is not None:
        pts = [matvec(R, p) for p in pts]
    off = [mpf(o) for o in offset]
    pts = [vadd(vscale(mpf(scale), p), off) for p in pts]
    return stencil(*pts)


def sample_hinges(seed, n_generic=12, hard=True):
    """Deterministic list of (label, x).  Generic random stencils plus the hard cases
    of STYLE.md: theta near 0 and near +-pi, needle triangles, a short hinge edge,
    a far offset and extreme scales."""
    rng = random.Random(seed)
    out = []
    for k in range(n_generic):
        while True:
            x = [mpf(rng.uniform(-1, 1)) for _ in range(12)]
            if well_separated(x, 0.1):
                break
        out.append(("generic-%d" % k, x))
    if not hard:
        return out

    def shape():
        return dict(l0=rng.uniform(0.7, 1.3), p0=rng.uniform(-0.3, 1.3), h0=rng.uniform(0.3, 1.2),
                    p3=rng.uniform(-0.3, 1.3), h3=rng.uniform(0.3, 1.2))
    pi = mpmath.pi
    for tag, beta in [("theta~1e-3", mpf("1e-3")), ("theta~-1e-6", mpf("-1e-6")),
                      ("theta~pi-1e-3", pi - mpf("1e-3")), ("theta~-(pi-1e-5)", -(pi - mpf("1e-5"))),
                      ("theta~2", mpf(2)), ("theta~-1", mpf(-1))]:
        out.append(("near-" + tag if "~" in tag else tag, make_hinge(beta=beta, R=rand_rotation(rng), **shape())))
    s = shape(); s["h0"] = 1e-3 * s["l0"]
    out.append(("needle-upper", make_hinge(beta=mpf("0.7"), R=rand_rotation(rng), **s)))
    s = shape(); s["h3"] = 1e-3 * s["l0"]; s["p3"] = 4.0
    out.append(("needle-lower-obtuse", make_hinge(beta=mpf("-2.3"), R=rand_rotation(rng), **s)))
    s = shape(); s["l0"] = 1e-3
    out.append(("short-hinge-edge", make_hinge(beta=mpf("1.1"), R=rand_rotation(rng), **s)))
    out.append(("offset-1e6", make_hinge(beta=mpf("0.4"), R=rand_rotation(rng), offset=(1e6, -2e6, 3e6), **shape())))
    out.append(("scale-1e-8", make_hinge(beta=mpf("-0.9"), R=rand_rotation(rng), scale=mpf("1e-8"), **shape())))
    out.append(("scale-1e8", make_hinge(beta=mpf("2.5"), R=rand_rotation(rng), scale=mpf("1e8"), **shape())))
    return out


def well_separated(x, ratio):
    """Both triangles have smallest altitude >= ratio * longest edge."""
    x0, x1, x2, x3 = (pt(x, i) for i in range(4))
    for tri in ((x0, x1, x2), (x3, x2, x1)):
        a, b, c = tri
        area2 = norm(cross(vsub(b, a), vsub(c, a)))
        ls = [norm(vsub(b, c)), norm(vsub(c, a)), norm(vsub(a, b))]
        if area2 / max(ls) < ratio * max(ls):
            return False
    return True


# ---------------------------------------------------------------- reporting
class Report:
    """Collects the assertions of one check script; finish() prints a summary and exits."""

    def __init__(self, name, description, falsify=None):
        self.name = name
        self.falsify = falsify
        self.failures = []
        self.count = 0
        print("== %s: %s" % (name, description))
        if falsify:
            print("== FALSIFIED RUN (%s): this run is expected to FAIL" % falsify)

    def small(self, label, value, tol):
        """Assert value <= tol (a residual)."""
        self.count += 1
        ok = value <= tol
        print("  [%s] %-62s residual %s (tol %s)" % ("ok" if ok else "FAIL", label,
                                                    mpmath.nstr(value, 3), mpmath.nstr(tol, 2)))
        if not ok:
            self.failures.append(label)
        return ok

    def large(self, label, value, floor):
        """Assert value >= floor (a quantity the claim says is nonzero)."""
        self.count += 1
        ok = value >= floor
        print("  [%s] %-62s value %s (must be >= %s)" % ("ok" if ok else "FAIL", label,
                                                         mpmath.nstr(value, 3), mpmath.nstr(floor, 2)))
        if not ok:
            self.failures.append(label)
        return ok

    def true(self, label, cond, detail=""):
        self.count += 1
        print("  [%s] %s%s" % ("ok" if cond else "FAIL", label, (": " + detail) if detail else ""))
        if not cond:
            self.failures.append(label)
        return cond

    def worst(self, label, values, tol):
        """Assert max(values) <= tol for a list of (case, residual); prints the worst case."""
        case, v = max(values, key=lambda cv: cv[1])
        return self.small("%s [worst of %d: %s]" % (label, len(values), case), v, tol)

    def finish(self):
        if self.failures:
            print("== %s: FAILED %d of %d assertions: %s" % (self.name, len(self.failures), self.count,
                                                           "; ".join(self.failures)))
            sys.exit(1)
        print("== %s: all %d assertions hold" % (self.name, self.count))
        sys.exit(0)


def parse_args(description, variants):
    """--falsify [VARIANT]: apply one of the named falsifications (the first is the default)."""
    p = argparse.ArgumentParser(description=description)
    names = list(variants)
    p.add_argument("--falsify", nargs="?", const=names[0], default=None, choices=names,
                   help="apply a falsification and expect failure; variants: " +
                   "; ".join("%s = %s" % kv for kv in variants.items()))
    return p.parse_args()


def run(main):
    """Run a check's main().  Exit status: 0 all assertions hold, 1 some assertion failed,
    2 internal error.  In a falsified run (--falsify, registered with WILL_FAIL) an internal
    error exits 0 instead, so that ctest reports the falsified test as FAILED rather than
    mistaking a crash for the expected failure."""
    import traceback
    try:
        main()
    except SystemExit:
        raise
    except Exception:
        traceback.print_exc()
        if "--falsify" in sys.argv:
            print("== INTERNAL ERROR in a falsified run: exiting 0 so that WILL_FAIL flags it")
            sys.exit(0)
        print("== INTERNAL ERROR")
        sys.exit(2)
