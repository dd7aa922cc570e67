#!/usr/bin/env python3
"""Check for proofs/quadratic-bending.md: the `quadratic` bending energy (the isometric bending
model of Bergou et al. 2006 and Wardetzky et al. 2007), in the contract's labels, and its relation
to the hinge energies.  Exact arithmetic only: SymPy on symbolic hinges, Python fractions on random
rational hinges (rational rotations from integer quaternions keep every length and area rational).

Definitions (docs/quantities.md, section `quadratic`): from the rest hinge R, with a1, a2 the
interior angles of the upper triangle (x0, x1, x2) at x1 and x2, and b1, b2 those of the lower
triangle (x3, x2, x1) at x1 and x2,
    K = ( -(cot a1 + cot a2),  cot a2 + cot b2,  cot a1 + cot b1,  -(cot b1 + cot b2) ),
    psi(X) = c_q |sum_j K_j x_j|^2,   c_q = 3 k / A_bar,   A_bar = sum of the two rest areas.

1. K: closed forms K_0 = -|e|^2/|N| = -|e|/h0, K_3 = -|e|/h~0; sum_j K_j = 0 for every hinge;
   Bergou's K = (c03 + c04, c01 + c02, -c01 - c03, -c02 - c04) in his labels is the same vector.
2. sum_j K_j x_j = |e| (m + m~) (m, m~ the outward in-plane edge normals) for every hinge built
   from the rest triangles by a fold about the hinge edge: |sum K x|^2 = 4 |e|^2 sin^2(theta/2)
   (symbolic); so sum K x = 0 exactly on flat rest hinges (theta_bar = 0) and only there (a
   rest hinge folded onto itself, theta_bar = pi, is coplanar but not flat).
3. On random rational flat rest hinges in general position: sum K x_bar = 0, psi(R) = 0 and the
   gradient at rest is exactly zero.
4. Isometric bends (a fold by theta plus any rigid motion, proper or improper): psi = 4 k a
   sin^2(theta/2) = 4 psi_willmore exactly, with cos theta from the contract's definition.
5. Series: psi_quad / psi_shells = (sin(theta/2) / (theta/2))^2 = 1 - theta^2/12 + theta^4/360
   - ...: the leading factor is exactly 1; psi_quad = cos^2(theta/2) psi_tan exactly.
6. grad psi = 2 c_q K_j (sum K x) and Hess psi = 2 c_q K K^T (x) I_3 against SymPy's
   differentiation; with sum K = 0: zero net force and torque for every X; energy invariant under
   rigid motions and reflections; Hess rho_w = 2 c_q K (x) (w x sum K x).
7. Linearization at a flat rest hinge: |e| grad theta = K (x) n (from the polynomials of the
   contract's definition), hence Hess psi_quad = Hess psi_shells(R) + 2 c_q K K^T (x) (I - n n^T):
   equal on out-of-plane displacements; an in-plane move of x0 costs c_q K_0^2 |d|^2 with theta
   still exactly 0; in-plane affine maps cost nothing; the kernel of Hess psi_quad (dimension 9)
   is exactly the displacements affine on the rest hinge; a uniform scaling s of X multiplies psi
   by s^2 and leaves theta.
--falsify half      : take Bergou's E_b = 1/2 x^T Q x as the per-hinge psi (constant 3/(2 A_bar))
--falsify own-angles: weight each hinge-edge vertex by its own angles (cot a1 + cot b1 at x1)
--falsify grad-no-2 : claim grad psi = c_q K_j (sum K x)
"""
import math
import random
from fractions import Fraction as Fr

import sympy as sp

import hinge_common as hc
from theta_oracle_poly import poly_jets

VARIANTS = {"half": "per-hinge psi with Bergou's 1/2 x^T Q x, i.e. 3 k / (2 A_bar)",
            "own-angles": "hinge-edge vertices weighted by their own angles",
            "grad-no-2": "grad psi = c_q K_j (sum K x), without the 2"}

FALSIFY = None


# ---------------------------------------------------------------- exact vectors (Fraction or SymPy)
# hinge_common's vector helpers are plain arithmetic: they take Fractions and SymPy expressions as they are.
sub, add, scale, dot, cross = hc.vsub, hc.vadd, hc.vscale, hc.dot, hc.cross


def fsqrt(q):
    """Exact square root of a nonnegative Fraction that is a perfect square (else an error)."""
    q = Fr(q)
    a, b = math.isqrt(q.numerator), math.isqrt(q.denominator)
    if a * a != q.numerator or b * b != q.denominator:
        raise ValueError("not a rational square: %s" % q)
    return Fr(a, b)


def ssqrt(e):
    return sp.sqrt(sp.factor(sp.simplify(e)))


def cot(v, p, q, sqrt):
    """Cotangent of the interior angle at v between v->p and v->q: (u.w) / |u x w|."""
    u, w = sub(p, v), sub(q, v)
    return dot(u, w) / sqrt(dot(cross(u, w), cross(u, w)))


def weights(R, sqrt, variant=None):
    """K of the rest hinge R = (x0, x1, x2, x3), in the contract's labels."""
    x0, x1, x2, x3 = R
    a1 = cot(x1, x2, x0, sqrt)   # upper triangle, at x1
    a2 = cot(x2, x0, x1, sqrt)   # upper triangle, at x2
    b1 = cot(x1, x3, x2, sqrt)   # lower triangle, at x1
    b2 = cot(x2, x1, x3, sqrt)   # lower triangle, at x2
    if variant == "own-angles":
        return [-(a1 + a2), a1 + b1, a2 + b2, -(b1 + b2)]
    return [-(a1 + a2), a2 + b2, a1 + b1, -(b1 + b2)]


def bergou_weights(B, sqrt):
    """Bergou et al. 2006's K in their own labels: B = (y0, y1, y2, y3), hinge edge e0 = y1 - y0,
    e1 = y2 - y0, e2 = y3 - y0, e3 = y2 - y1, e4 = y3 - y1; c_jk the cotangent of the interior
    angle between e_j and e_k at their common vertex."""
    y0, y1, y2, y3 = B
    c01 = cot(y0, y1, y2, sqrt)
    c02 = cot(y0, y1, y3, sqrt)
    c03 = cot(y1, y0, y2, sqrt)
    c04 = cot(y1, y0, y3, sqrt)
    return [c03 + c04, c01 + c02, -c01 - c03, -c02 - c04]


def ksum(K, X):
    out = [0, 0, 0]
    for Kj, xj in zip(K, X):
        out = add(out, scale(Kj, xj))
    return out


def areas_sum(R, sqrt):
    x0, x1, x2, x3 = R
    N = cross(sub(x1, x0), sub(x2, x0))
    Nt = cross(sub(x2, x3), sub(x1, x3))
    return (sqrt(dot(N, N)) + sqrt(dot(Nt, Nt))) / 2


def const(A_bar, k=1):
    """c_q = 3 k / A_bar (the contract); 'half' takes Bergou's 1/2 x^T Q x per hinge."""
    return (Fr(3, 2) if FALSIFY == "half" else 3) * k / A_bar


def contract_parts(X):
    """N, Nt, e0 and the polynomials P = (N x Nt).e0, X = N.Nt of the contract's definition."""
    x0, x1, x2, x3 = X
    N = cross(sub(x1, x0), sub(x2, x0))
    Nt = cross(sub(x2, x3), sub(x1, x3))
    e0 = sub(x2, x1)
    return N, Nt, e0, dot(cross(N, Nt), e0), dot(N, Nt)


# ---------------------------------------------------------------- random rational hinges
def rational_rotation(rng, improper=False):
    while True:
        a, b, c, d = (rng.randint(-9, 9) for _ in range(4))
        n = a * a + b * b + c * c + d * d
        if n:
            break
    M = [[a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)],
         [2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)],
         [2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d]]
    s = -1 if improper else 1
    return [[Fr(s * m, n) for m in row] for row in M]


def apply(Q, b, X):
    return [add([dot(Q[i], x) for i in range(3)], b) for x in X]


def rfr(rng, lo, hi, den=16):
    return Fr(rng.randint(int(lo * den), int(hi * den)), den)


def local_shape(rng, kind):
    """Intrinsic shape: hinge edge length l, apex x0 at (p0, h0), apex x3 at (p3, -h3)."""
    l = rfr(rng, 0.5, 3)
    p0, p3 = rfr(rng, -1, 2) * l, rfr(rng, -1, 2) * l
    h0, h3 = rfr(rng, 0.1, 2) * l, rfr(rng, 0.1, 2) * l
    if kind == "needle":
        h0 = l / 1000
    elif kind == "obtuse":
        p3 = 4 * l
    elif kind == "short-edge":
        l = Fr(1, 1000)
    return l, p0, h0, p3, h3


def folded(shape, t):
    """The hinge with the lower triangle turned about the hinge edge by phi, tan(phi/2) = t
    (t = 0: flat).  Returns the four points and (cos phi, sin phi)."""
    l, p0, h0, p3, h3 = shape
    c, s = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
    zero = 0 * l
    return ([[p0, h0, zero], [zero, zero, zero], [l, zero, zero], [p3, -h3 * c, h3 * s]], (c, s))


def random_cases(rng, n):
    kinds = ["generic"] * (n - 3) + ["needle", "obtuse", "short-edge"]
    return [(kind, local_shape(rng, kind)) for kind in kinds]


# ---------------------------------------------------------------- the checks
def check_weights_symbolic(rep):
    l, h0, h3 = sp.symbols("l h0 h3", positive=True)
    p0, p3 = sp.symbols("p0 p3", real=True)
    R, _ = folded((l, p0, h0, p3, h3), sp.Integer(0))
    R = [[sp.sympify(c) for c in x] for x in R]
    K = weights(R, ssqrt, FALSIFY)
    closed = [-l / h0, (l - p0) / h0 + (l - p3) / h3, p0 / h0 + p3 / h3, -l / h3]
    rep.true("K from the cotangents = (-|e|/h0, (l-p0)/h0 + (l-p3)/h3, p0/h0 + p3/h3, -|e|/h~0)"
             " on the symbolic hinge (edge l, apices (p0, h0), (p3, -h3))",
             all(sp.simplify(a - b) == 0 for a, b in zip(K, closed)),
             str([sp.simplify(k) for k in K]))
    rep.true("sum_j K_j = 0 for every hinge (K depends on the two triangles' shapes only)",
             sp.simplify(sum(K)) == 0)
    N = cross(sub(R[1], R[0]), sub(R[2], R[0]))
    rep.true("K_0 = -|e|^2 / |N| (= -|e| / h0)",
             sp.simplify(K[0] + dot(sub(R[2], R[1]), sub(R[2], R[1])) / ssqrt(dot(N, N))) == 0)
    # the cotangents in the edge vectors of docs/quantities.md: e1 = x0 - x2, e2 = x1 - x0,
    # e~1 = x3 - x2, e~2 = x1 - x3; |N|, |Nt| twice the areas
    x0, x1, x2, x3 = R
    e0, e1, e2, et1, et2 = sub(x2, x1), sub(x0, x2), sub(x1, x0), sub(x3, x2), sub(x1, x3)
    Nt = cross(sub(x2, x3), sub(x1, x3))
    nN, nNt = ssqrt(dot(N, N)), ssqrt(dot(Nt, Nt))
    forms = [-dot(e0, e2) / nN, -dot(e0, e1) / nN, -dot(e0, et2) / nNt, -dot(e0, et1) / nNt]
    cots = [cot(x1, x2, x0, ssqrt), cot(x2, x0, x1, ssqrt), cot(x1, x3, x2, ssqrt), cot(x2, x1, x3, ssqrt)]
    rep.true("cot alpha1 = -(e0.e2)/|N|, cot alpha2 = -(e0.e1)/|N|, cot alpha~1 = -(e0.e~2)/|Nt|,"
             " cot alpha~2 = -(e0.e~1)/|Nt|", all(sp.simplify(a - b) == 0 for a, b in zip(forms, cots)))
    # Bergou's labels: y0, y1 the hinge edge, y2, y3 the apices; either orientation, either apex
    same = []
    for B in ([R[1], R[2], R[0], R[3]], [R[2], R[1], R[3], R[0]]):
        KB = bergou_weights(B, ssqrt)
        perm = [KB[2], KB[0], KB[1], KB[3]] if B[0] is R[1] else [KB[3], KB[1], KB[0], KB[2]]
        same.append(all(sp.simplify(a - b) == 0 for a, b in zip(perm, K)))
    rep.true("Bergou's K = (c03 + c04, c01 + c02, -c01 - c03, -c02 - c04) on (y0, y1, y2, y3) ="
             " (x1, x2, x0, x3) is the same vector (also with y0 <-> y1, y2 <-> y3)", all(same))


def check_fold_symbolic(rep):
    l, h0, h3 = sp.symbols("l h0 h3", positive=True)
    p0, p3, t = sp.symbols("p0 p3 t", real=True)
    shape = (l, p0, h0, p3, h3)
    R, _ = folded(shape, sp.Integer(0))
    X, (c, s) = folded(shape, t)
    R = [[sp.sympify(v) for v in x] for x in R]
    K = weights(R, ssqrt, FALSIFY)
    S = [sp.simplify(v) for v in ksum(K, X)]
    m, mt = [0, -1, 0], [0, c, -s]            # outward in-plane edge normals of the two triangles
    rep.true("sum K x = |e| (m + m~) for the fold by phi (tan(phi/2) = t) of any hinge",
             all(sp.simplify(a - l * (b1 + b2)) == 0 for a, b1, b2 in zip(S, m, mt)), str(S))
    sq = sp.simplify(dot(S, S))
    rep.true("|sum K x|^2 = 4 |e|^2 t^2 / (1 + t^2) = 4 |e|^2 sin^2(phi/2) (no altitude, no offset)",
             sp.simplify(sq - 4 * l ** 2 * t ** 2 / (1 + t ** 2)) == 0, str(sp.factor(sq)))
    # phi is |theta|: cos theta from the contract's polynomials
    N, Nt, e0, P, Xd = contract_parts(X)
    cos_theta = sp.simplify(Xd / (ssqrt(dot(N, N)) * ssqrt(dot(Nt, Nt))))
    sin_theta = sp.simplify(P / (ssqrt(dot(e0, e0)) * ssqrt(dot(N, N)) * ssqrt(dot(Nt, Nt))))
    rep.true("the contract's theta of that hinge: cos theta = cos phi, sin theta = -sin phi (|theta| = |phi|)",
             sp.simplify(cos_theta - c) == 0 and sp.simplify(sin_theta + s) == 0,
             "cos %s, sin %s" % (cos_theta, sin_theta))
    # rest hinges: flat (t = 0) gives 0, folded onto itself (t -> infinity, theta_bar = pi) gives 4|e|^2
    rep.true("rest hinge: |sum K x_bar|^2 = 4 |e|^2 sin^2(theta_bar/2): 0 iff flat, 4|e|^2 folded onto itself",
             sq.subs(t, 0) == 0 and sp.limit(sq, t, sp.oo) == 4 * l ** 2)


def check_flat_rest(rep, rng):
    worst_sum, worst_rest, count = 0, 0, 0
    for kind, shape in random_cases(rng, 60):
        R, _ = folded(shape, Fr(0))
        Q, b = rational_rotation(rng, improper=rng.random() < 0.3), [rfr(rng, -50, 50) for _ in range(3)]
        R = apply(Q, b, R)
        K = weights(R, fsqrt, FALSIFY)
        S = ksum(K, R)
        worst_sum = max(worst_sum, abs(sum(K)))
        c = const(areas_sum(R, fsqrt))
        grad = [scale(2 * c * Kj, S) for Kj in K]
        worst_rest = max(worst_rest, max(abs(v) for v in S), c * dot(S, S), max(abs(v) for g in grad for v in g))
        count += 1
    rep.true("sum K = 0 exactly on %d random rational rest hinges (generic, needle, obtuse, short edge)" % count,
             worst_sum == 0)
    rep.true("flat rest hinges in general position: sum K x_bar = 0, psi(R) = 0, grad psi(R) = 0, exactly",
             worst_rest == 0, "largest |entry| %s" % (float(worst_rest)))


def check_isometric(rep, rng):
    bad, count = [], 0
    for kind, shape in random_cases(rng, 40):
        l = shape[0]
        R, _ = folded(shape, Fr(0))
        Q0, b0 = rational_rotation(rng), [rfr(rng, -9, 9) for _ in range(3)]
        R = apply(Q0, b0, R)
        K = weights(R, fsqrt, FALSIFY)
        A_bar = areas_sum(R, fsqrt)
        for t in (Fr(1, 1000), rfr(rng, -3, 3), Fr(7, 3)):
            X, _ = folded(shape, t)
            X = apply(rational_rotation(rng, improper=rng.random() < 0.5), [rfr(rng, -9, 9) for _ in range(3)], X)
            N, Nt, e0, P, Xd = contract_parts(X)
            cos_theta = Xd / (fsqrt(dot(N, N)) * fsqrt(dot(Nt, Nt)))
            S = ksum(K, X)
            psi = const(A_bar) * dot(S, S)
            a = 3 * l * l / A_bar
            willmore = a * (1 - cos_theta) / 2          # k a sin^2(theta/2), k = 1
            count += 1
            if psi != 4 * willmore or dot(S, S) != 2 * l * l * (1 - cos_theta):
                bad.append((kind, t))
    rep.true("isometric bends (%d: fold by theta, then a rational rigid motion, proper or improper):"
             " psi = 4 k a sin^2(theta/2) = 4 psi_willmore exactly" % count, not bad, str(bad[:3]))


def check_series(rep):
    th, k, a = sp.symbols("theta k a", positive=True)
    c_over_a = sp.Rational(3, 2) if FALSIFY == "half" else sp.Integer(3)   # c_q |e|^2 / k
    # on isometric bends |sum K x|^2 = 4 |e|^2 sin^2(theta/2), so psi_quad = (c_q |e|^2) 4 sin^2(theta/2)
    psi_quad = k * a * (c_over_a / 3) * 4 * sp.sin(th / 2) ** 2
    psi_shells = k * a * th ** 2
    psi_tan = k * a * (2 * sp.tan(th / 2)) ** 2
    psi_will = k * a * sp.sin(th / 2) ** 2
    ratio = sp.series(psi_quad / psi_shells, th, 0, 6).removeO()
    rep.true("psi_quad / psi_shells = 1 - theta^2/12 + theta^4/360 + O(theta^6): leading factor exactly 1",
             sp.simplify(ratio - (1 - th ** 2 / 12 + th ** 4 / 360)) == 0, str(ratio))
    rep.true("psi_quad = k a theta^2 - k a theta^4 / 12 + O(theta^6) (the first term is shells')",
             sp.simplify(sp.series(psi_quad, th, 0, 6).removeO() - (k * a * th ** 2 - k * a * th ** 4 / 12)) == 0)
    rep.true("psi_quad = cos^2(theta/2) psi_tan and = 4 psi_willmore exactly on isometric bends",
             sp.simplify(psi_quad - sp.cos(th / 2) ** 2 * psi_tan) == 0 and sp.simplify(psi_quad - 4 * psi_will) == 0)


def check_derivatives(rep, rng):
    xs = sp.symbols("x0:12", real=True)
    Ks = sp.symbols("K0:4", real=True)
    c = sp.Symbol("c", positive=True)
    X = [list(xs[3 * j:3 * j + 3]) for j in range(4)]
    S = ksum(Ks, X)
    psi = c * dot(S, S)
    factor = 1 if FALSIFY == "grad-no-2" else 2
    g_claim = [factor * c * Ks[j] * S[i] for j in range(4) for i in range(3)]
    g = [sp.diff(psi, v) for v in xs]
    rep.true("grad psi = 2 c_q K_j (sum K x) against SymPy's differentiation (symbolic x, K, c_q)",
             all(sp.expand(a - b) == 0 for a, b in zip(g, g_claim)))
    H_ok = all(sp.expand(sp.diff(g[r], xs[s]) - 2 * c * Ks[r // 3] * Ks[s // 3] * (1 if r % 3 == s % 3 else 0)) == 0
               for r in range(12) for s in range(12))
    rep.true("Hess psi = 2 c_q K K^T (x) I_3, constant (symbolic)", H_ok)
    # with sum K = 0: net force and torque vanish identically, for every X
    sub0 = {Ks[3]: -Ks[0] - Ks[1] - Ks[2]}
    gv = [[gc.subs(sub0) for gc in g_claim[3 * j:3 * j + 3]] for j in range(4)]
    force = [sp.expand(sum(gv[j][i] for j in range(4))) for i in range(3)]
    torque = [sp.expand(v) for v in
              [sum(cross(X[j], gv[j])[i] for j in range(4)) for i in range(3)]]
    rep.true("sum K = 0 => zero net force and zero net torque for every X (symbolic)",
             all(v == 0 for v in force + torque), "force %s torque %s" % (force, torque))
    w = sp.symbols("w0:3", real=True)
    rho = [cross(w, X[j]) for j in range(4)]
    Hrho = [[2 * c * Ks[j] * ksum(Ks, rho)[i] for i in range(3)] for j in range(4)]
    claim = [[2 * c * Ks[j] * cross(w, S)[i] for i in range(3)] for j in range(4)]
    rep.true("Hess rho_w = 2 c_q K (x) (w x sum K x): rotations are null vectors only at rest or about sum K x",
             all(sp.expand(Hrho[j][i] - claim[j][i]) == 0 for j in range(4) for i in range(3)))
    # exact rigid-motion invariance of the energy on random rational X (proper and improper)
    ok = True
    for _ in range(20):
        Kr = [rfr(rng, -3, 3) for _ in range(3)]
        Kr.append(-sum(Kr))
        Xr = [[rfr(rng, -5, 5) for _ in range(3)] for _ in range(4)]
        Q, b = rational_rotation(rng, improper=rng.random() < 0.5), [rfr(rng, -9, 9) for _ in range(3)]
        S0, S1 = ksum(Kr, Xr), ksum(Kr, apply(Q, b, Xr))
        ok &= dot(S0, S0) == dot(S1, S1) and S1 == [dot(Q[i], S0) for i in range(3)]
    rep.true("psi(Q X + b) = psi(X) and sum K (Q x + b) = Q sum K x, exactly (20 random X, Q orthogonal)", ok)


def check_linearization(rep, rng):
    bad_grad, bad_hess, bad_inplane, bad_affine, bad_scale, count = [], [], [], [], [], 0
    for kind, shape in random_cases(rng, 24):
        l = shape[0]
        R, _ = folded(shape, Fr(0))
        Q, b = rational_rotation(rng), [rfr(rng, -9, 9) for _ in range(3)]
        R = apply(Q, b, R)
        K = weights(R, fsqrt, FALSIFY)
        A_bar = areas_sum(R, fsqrt)
        c = const(A_bar)
        N, Nt, e0, P, Xd = contract_parts(R)
        n = scale(1 / fsqrt(dot(N, N)), N)
        (_, gP, _), _, _ = poly_jets(*[v for x in R for v in x])
        # at a flat hinge P = 0 and X > 0, so grad theta = grad P / (|e0| X): |e| grad theta = grad P / X
        e_grad = [Fr(v) / Xd for v in gP]
        count += 1
        if P != 0 or Xd <= 0 or any(e_grad[3 * j + i] != K[j] * n[i] for j in range(4) for i in range(3)):
            bad_grad.append(kind)
        # Hess psi_shells(R) = 2 k a grad theta grad theta^T (psi' = 0 at rest), k = 1
        a = 3 * l * l / A_bar
        for r in range(12):
            for s in range(12):
                hq = 2 * c * K[r // 3] * K[s // 3] * (1 if r % 3 == s % 3 else 0)
                hs = 2 * a * e_grad[r] * e_grad[s] / (l * l)
                proj = (1 if r % 3 == s % 3 else 0) - n[r % 3] * n[s % 3]
                if hq - hs != 2 * c * K[r // 3] * K[s // 3] * proj:
                    bad_hess.append(kind)
        # an in-plane move of x0: theta stays exactly 0, psi_quad = c K0^2 |d|^2 > 0
        m = cross(n, sub(R[2], R[1]))
        d = add(scale(rfr(rng, -1, 1) * l / 4, sub(R[2], R[1])), scale(rfr(rng, 0.05, 0.2), m))
        X = [add(R[0], d)] + R[1:]
        _, _, _, P1, X1 = contract_parts(X)
        S = ksum(K, X)
        if P1 != 0 or X1 <= 0 or c * dot(S, S) != c * K[0] ** 2 * dot(d, d) or dot(d, d) == 0:
            bad_inplane.append(kind)
        # an in-plane affine map (a shear along the edge plus a stretch across it) costs nothing
        u = scale(1 / l, sub(R[2], R[1]))
        mu = scale(1 / fsqrt(dot(m, m)), m)
        sh, st = rfr(rng, -1, 1), rfr(rng, 0.5, 2)

        def affine(x):
            y = sub(x, R[1])
            return add(R[1], add(y, add(scale(sh * dot(y, mu), u), scale((st - 1) * dot(y, mu), mu))))
        S = ksum(K, [affine(x) for x in R])
        if any(v != 0 for v in S):
            bad_affine.append(kind)
        # a uniform scaling of a folded hinge: psi * s^2, theta unchanged
        Xf, _ = folded(shape, Fr(1, 3))
        sc = rfr(rng, 1.1, 3)
        S1, S2 = ksum(K, apply(Q, b, Xf)), ksum(K, apply(Q, b, [scale(sc, x) for x in Xf]))
        if dot(S2, S2) != sc * sc * dot(S1, S1):
            bad_scale.append(kind)
    # the kernel of Hess psi_quad = {v : sum K_j v_j = 0} (dimension 9) is exactly the displacements
    # that are affine on the flat rest hinge, v_j = L x_bar_j + t (12 parameters, image of dimension 9)
    kernel_ok = True
    for kind, shape in random_cases(rng, 6):
        R, _ = folded(shape, Fr(0))
        R = apply(rational_rotation(rng), [rfr(rng, -9, 9) for _ in range(3)], R)
        K = weights(R, fsqrt, FALSIFY)
        cols = []
        for a_ in range(3):
            for b_ in range(3):
                cols.append([(x[b_] if i == a_ else 0) for x in R for i in range(3)])
            cols.append([(1 if i == a_ else 0) for x in R for i in range(3)])
        M = sp.Matrix(12, 12, lambda r, s: sp.Rational(cols[s][r].numerator, cols[s][r].denominator)
                      if isinstance(cols[s][r], Fr) else sp.Integer(cols[s][r]))
        H = sp.Matrix(12, 12, lambda r, s: sp.Rational(2 * K[r // 3] * K[s // 3]) * (1 if r % 3 == s % 3 else 0))
        Hrank = H.rank()
        kernel_ok &= M.rank() == 9 and Hrank == 3 and (H * M).is_zero_matrix
    rep.true("ker Hess psi_quad (dimension 9, rank 3) = the displacements affine on the flat rest hinge",
             kernel_ok)
    rep.true("flat rest hinges (%d): |e| grad theta = K_j n per vertex, exactly (from the contract's"
             " polynomials)" % count, not bad_grad, str(bad_grad[:3]))
    rep.true("Hess psi_quad = Hess psi_shells(R) + 2 c_q K K^T (x) (I - n n^T), exactly: the two agree on"
             " out-of-plane displacements", not bad_hess, str(sorted(set(bad_hess))[:3]))
    rep.true("in-plane move d of x0: theta stays exactly 0 (shells 0), psi_quad = c_q K_0^2 |d|^2 > 0",
             not bad_inplane, str(bad_inplane[:3]))
    rep.true("in-plane affine maps of a flat rest hinge (shear, stretch): sum K x = 0, psi_quad = 0",
             not bad_affine, str(bad_affine[:3]))
    rep.true("uniform scaling s of a folded hinge: psi_quad * s^2 (theta unchanged)", not bad_scale)


def main():
    global FALSIFY
    args = hc.parse_args(__doc__, VARIANTS)
    FALSIFY = args.falsify
    rep = hc.Report("proofs.quadratic-bending",
                    "the quadratic (isometric) bending energy, its weights, and shells to leading order",
                    args.falsify)
    rng = random.Random(2006)
    check_weights_symbolic(rep)
    check_fold_symbolic(rep)
    check_flat_rest(rep, rng)
    check_isometric(rep, rng)
    check_series(rep)
    check_derivatives(rep, rng)
    check_linearization(rep, rng)
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
