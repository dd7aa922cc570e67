#!/usr/bin/env python3
"""Check for proofs/gradient.md: eq. (4), the gradient of theta.

1. Exact identities (the derivation's last step): with theta = atan2(y, X), y = |e0| D,
   D = det[e0, a, b], X = N.Nt, one has d theta = (X dy - y dX) / (|N|^2 |Nt|^2), and eq. (4)
   multiplied by |e0| |N|^2 |Nt|^2 becomes four polynomial identities (G0)-(G3) in the 12
   coordinates.  They are verified by exact integer evaluation (Schwartz-Zippel) at random
   points with 62-bit coordinates: a nonzero polynomial of degree <= 9 vanishes at such a
   point with probability <= 9/2^63, so 16 points leave a false-acceptance probability
   below 2^-900.
2. Eq. (4) as printed (literal transcription: n, nt, h_i, h~_i, cos alpha_i, cos alpha~_i) against
   the SymPy gradient of the CONVENTIONS definition (theta_oracle.py), 256 bits, random and
   hard stencils; the oracle itself against 400-bit finite differences.
0. The oracle's generated code (theta_oracle_poly.py) agrees exactly with a fresh SymPy run.
3. The lemmas used in gradient.md: d n/d x_i = m_i n^T / h_i; d theta = -m0.dn - m~0.dnt;
   1/h0 = cos a2/h1 + cos a1/h2; c_i/h_i = -(e^0 . e_i)/(2A); sum_j g_j = 0, sum_j x_j x g_j = 0.
--falsify swap-alpha: cos alpha_1 and cos alpha_2 exchanged in eq. (4) (both triangles).
--falsify lower-normal: the lower terms use the normal of the tilde label order (x3,x1,x2) (= -nt).
"""
import random

import sympy as sp
from mpmath import mp, mpf

import hinge_common as hc
from hinge_common import vsub, vadd, dot, cross, norm, pt
import paper_formulas as pf
import theta_oracle as to

VARIANTS = {"swap-alpha": "cos alpha_1 <-> cos alpha_2 in eq. (4)",
            "lower-normal": "lower terms of eq. (4) with the normal of the tilde label order (-nt)"}


def schwartz_zippel(rep, falsify):
    X = sp.symbols("x0:12")
    x0, x1, x2, x3 = [sp.Matrix(X[3 * i:3 * i + 3]) for i in range(4)]
    e0, a, b = x2 - x1, x0 - x1, x1 - x3
    N = (x1 - x0).cross(x2 - x0)
    Nt = (x2 - x3).cross(x1 - x3)
    D = sp.Matrix.hstack(e0, a, b).det()
    XX = N.dot(Nt)
    L2 = e0.dot(e0)
    NN, TT = N.dot(N), Nt.dot(Nt)

    def grad(f, k):
        return sp.Matrix([sp.diff(f, X[3 * k + c]) for c in range(3)])
    # right-hand sides: |e0| |N|^2 |Nt|^2 times eq. (4), using c_i/h_i = -(e0.e_i)/(|e0| |N|)
    e1, e2 = x0 - x2, x1 - x0                   # upper edges
    t1, t2 = x3 - x2, x1 - x3                   # lower edges in tilde labels (x3, x1, x2)
    if falsify == "swap-alpha":                 # cos a1/h1 = -(e0.e2) l1/(l0 l2 2A): not polynomial;
        e1, e2, t1, t2 = e2, e1, t2, t1         # use the exchanged polynomial forms instead
    sgn = -1 if falsify == "lower-normal" else 1
    ids = {
        "G0": (XX * grad(D, 0) - D * grad(XX, 0), -TT * N),
        "G1": (-XX * D * e0 + L2 * (XX * grad(D, 1) - D * grad(XX, 1)),
               -(e0.dot(e1)) * TT * N - sgn * (e0.dot(t1)) * NN * Nt),
        "G2": (XX * D * e0 + L2 * (XX * grad(D, 2) - D * grad(XX, 2)),
               -(e0.dot(e2)) * TT * N - sgn * (e0.dot(t2)) * NN * Nt),
        "G3": (XX * grad(D, 3) - D * grad(XX, 3), -sgn * NN * Nt),
    }
    rng = random.Random(4)
    pts = [[rng.randint(-2 ** 62, 2 ** 62) for _ in range(12)] for _ in range(16)]
    for name, (lhs, rhs) in ids.items():
        f = sp.lambdify(X, list(lhs - rhs), modules=[{}])
        bad = sum(1 for p in pts if any(v != 0 for v in f(*p)))
        rep.true("exact (Schwartz-Zippel, 16 integer points): identity %s" % name, bad == 0,
                 "%d of 16 points nonzero" % bad)


def generated_code_fresh(rep):
    """The oracle's generated polynomial derivatives equal a fresh SymPy differentiation
    (Poly.diff), exactly, at random integer points (Schwartz-Zippel, degree <= 5)."""
    import gen_theta_oracle_poly as gen
    from theta_oracle_poly import poly_jets
    X, polys = gen.polynomials()
    rng = random.Random(9)
    pts = [[rng.randint(-2 ** 62, 2 ** 62) for _ in range(12)] for _ in range(3)]
    vals = [poly_jets(*p) for p in pts]
    ok = True
    for k, poly in enumerate(polys):
        pp = sp.Poly(poly, *X)
        g = [pp.diff(s) for s in X]
        h = [[gi.diff(s) for s in X] for gi in g]
        for v, p in zip(vals, pts):
            ok = ok and [pp(*p), [q(*p) for q in g], [[q(*p) for q in r] for r in h]] == v[k]
    rep.true("theta_oracle_poly.py (generated) = fresh SymPy derivatives, exact at 3 integer points", ok)


def main():
    args = hc.parse_args(__doc__, VARIANTS)
    hc.setup()
    rep = hc.Report("proofs.gradient", "eq. (4) from the definition of theta", args.falsify)
    generated_code_fresh(rep)
    schwartz_zippel(rep, args.falsify)
    oracle = to.ThetaOracle()
    tol = mpf(10) ** -40
    cases = hc.sample_hinges(21)
    res, sums, torque = [], [], []
    for lab, x in cases:
        _, g, _ = oracle(x, want_hess=False)
        g4 = pf.gradient_eq4(x, swap_alpha=args.falsify == "swap-alpha",
                             lower_normal_sign=-1 if args.falsify == "lower-normal" else 1)
        res.append((lab, hc.rel(g4, g)))
        gs = [pt(g4, j) for j in range(4)]
        scale = hc.fnorm(g4)
        sums.append((lab, norm(vadd(vadd(gs[0], gs[1]), vadd(gs[2], gs[3]))) / scale))
        tq = [mpf(0)] * 3
        for j in range(4):
            tq = vadd(tq, cross(vsub(pt(x, j), pt(x, 1)), gs[j]))
        torque.append((lab, norm(tq) / (scale * norm(vsub(pt(x, 2), pt(x, 1))))))
    rep.worst("eq. (4) vs SymPy gradient of the definition", res, tol)
    rep.worst("eq. (4): sum_j grad_xj = 0 (translation invariance)", sums, tol)
    rep.worst("eq. (4): sum_j (x_j - x1) x grad_xj = 0 (rotation invariance)", torque, tol)

    # the oracle against finite differences of the bare definition
    fd = []
    for lab, x in cases[:2] + cases[-4:-3]:
        _, g, _ = oracle(x, want_hess=False)
        mp.prec = 400
        gf = to.fd_gradient(to.theta_direct, x, mpf(10) ** -24)
        mp.prec = hc.PREC_BITS
        fd.append((lab, hc.rel(g, gf)))
    rep.worst("oracle vs 400-bit finite differences of the definition", fd, mpf(10) ** -60)

    # lemmas of gradient.md
    r_dn, r_dth, r_h, r_f = [], [], [], []
    rng = random.Random(5)
    for lab, x in cases[:8]:
        T, L = pf.upper(x), pf.lower(x)
        mp.prec = 400
        h = mpf(10) ** -24
        for i in range(3):       # d n / d x_i = m_i n^T / h_i, Jacobian by finite differences
            def nfun(y, i=i):
                xx = list(x); xx[3 * i:3 * i + 3] = y
                return pf.upper(xx).n
            J = to.fd_jacobian(nfun, pt(x, i), h)
            r_dn.append((lab, hc.rel(J, hc.mscale(1 / T.h[i], hc.outer(T.m[i], T.n)))))
        v = [mpf(rng.uniform(-1, 1)) for _ in range(12)]
        line = lambda s: [xi + s * vi for xi, vi in zip(x, v)]
        W = {-2: mpf(1) / 12, -1: mpf(-2) / 3, 1: mpf(2) / 3, 2: mpf(-1) / 12}
        dth = sum(w * to.theta_direct(line(k * h)) for k, w in W.items()) / h
        dn = [sum(w * pf.upper(line(k * h)).n[c] for k, w in W.items()) / h for c in range(3)]
        dnt = [sum(w * pf.lower(line(k * h)).n[c] for k, w in W.items()) / h for c in range(3)]
        mp.prec = hc.PREC_BITS
        r_dth.append((lab, abs(dth + dot(T.m[0], dn) + dot(L.m[0], dnt)) / abs(dth)))
        for Tr in (T, L):
            r_h.append((lab, abs(1 / Tr.h[0] - Tr.cos[2] / Tr.h[1] - Tr.cos[1] / Tr.h[2]) * Tr.h[0]))
            c = pf.c_coef(Tr)
            for i in range(3):
                f = -dot(Tr.eh[0], Tr.e[i]) / (2 * Tr.A)
                r_f.append((lab, abs(c[i] / Tr.h[i] - f) * Tr.h[0]))
    rep.worst("lemma: d n / d x_i = m_i n^T / h_i (400-bit differences)", r_dn, mpf(10) ** -60)
    rep.worst("lemma: d theta = -m0 . dn - m~0 . dnt (random directions)", r_dth, mpf(10) ** -60)
    rep.worst("lemma: 1/h0 = cos a2/h1 + cos a1/h2 (both triangles)", r_h, tol)
    rep.worst("lemma: c_i/h_i = -(e^0 . e_i)/(2A), c = (-1, cos a2, cos a1)", r_f, tol)
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
