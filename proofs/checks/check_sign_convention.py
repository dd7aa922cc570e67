#!/usr/bin/env python3
"""Check for proofs/sign-convention.md: the sign convention of theta, the atan2 form
of docs/contract.md, the identities behind it, and eq. (12).

Symbolic (SymPy, exact polynomial identities in the 12 coordinates):
  N = e0 x a, Nt = e0 x b                       (a = x0 - x1, b = x1 - x3)
  N x Nt = det[e0, a, b] e0
  N . Nt = |e0|^2 (a . b) - (e0 . a)(e0 . b)
  |u x v|^2 + (u . v)^2 = |u|^2 |v|^2            (so the atan2 arguments are |N||Nt|(sin, cos))
  relabelling (x0,x1,x2,x3) -> (x3,x2,x1,x0) leaves numerator and denominator unchanged;
  a reflection, or swapping x1 <-> x2 alone, negates the numerator only.
Numeric (mpmath, 256 bits, random and hard stencils):
  atan2(((N x Nt).e0)/|e0|, N.Nt) = atan2(|e0| det[e0,a,b], N.Nt);
  eq. (12) tan(theta/2) = sgn(det[n, nt, e0]) |n - nt| / |n + nt|, and the half-angle
  formulas sin(|theta|/2) = |n - nt|/2, cos(theta/2) = |n + nt|/2;
  the CONVENTIONS check values; lifting x0 along +n makes theta negative; a roof whose
  normals point away from each other has theta > 0; the folded-flat hinge gives +pi.
--falsify sign: theta is taken with the opposite sign (atan2(-num, den)).
"""
import sympy as sp
import mpmath
from mpmath import mpf

import hinge_common as hc
from hinge_common import vsub, vadd, vscale, dot, cross, norm, unit, det3, pt

VARIANTS = {"sign": "theta with the opposite sign, atan2(-((N x Nt).e0)/|e0|, N.Nt)"}


def symbolic(rep):
    X = sp.symbols("x0:12", real=True)
    x0, x1, x2, x3 = [sp.Matrix(X[3 * i:3 * i + 3]) for i in range(4)]
    e0, a, b = x2 - x1, x0 - x1, x1 - x3
    N = (x1 - x0).cross(x2 - x0)
    Nt = (x2 - x3).cross(x1 - x3)
    D = sp.Matrix.hstack(e0, a, b).det()

    def zero(v):
        return all(sp.expand(c) == 0 for c in (v if isinstance(v, sp.MatrixBase) else [v]))
    rep.true("symbolic: N = e0 x a and Nt = e0 x b", zero(N - e0.cross(a)) and zero(Nt - e0.cross(b)))
    rep.true("symbolic: N x Nt = det[e0, a, b] e0", zero(N.cross(Nt) - D * e0))
    rep.true("symbolic: N . Nt = |e0|^2 (a.b) - (e0.a)(e0.b)",
             zero(N.dot(Nt) - (e0.dot(e0) * a.dot(b) - e0.dot(a) * e0.dot(b))))
    U = sp.Matrix(sp.symbols("u0:3", real=True)); V = sp.Matrix(sp.symbols("v0:3", real=True))
    rep.true("symbolic: |u x v|^2 + (u.v)^2 = |u|^2 |v|^2 (Lagrange)",
             zero(U.cross(V).dot(U.cross(V)) + U.dot(V) ** 2 - U.dot(U) * V.dot(V)))
    num = N.cross(Nt).dot(e0)           # = |e0|^2 det[e0, a, b]
    den = N.dot(Nt)

    def relabel(expr, perm, M=None):
        sub = {}
        for k in range(4):
            src = sp.Matrix(X[3 * perm[k]:3 * perm[k] + 3])
            if M is not None:
                src = M * src
            for c in range(3):
                sub[X[3 * k + c]] = src[c]
        return expr.xreplace(sub)
    rep.true("symbolic: relabelling x0<->x3, x1<->x2 leaves numerator and N.Nt unchanged",
             zero(relabel(num, (3, 2, 1, 0)) - num) and zero(relabel(den, (3, 2, 1, 0)) - den))
    refl = sp.diag(-1, 1, 1)
    rep.true("symbolic: reflection x -> diag(-1,1,1) x negates numerator, keeps N.Nt",
             zero(relabel(num, (0, 1, 2, 3), refl) + num) and zero(relabel(den, (0, 1, 2, 3), refl) - den))
    rep.true("symbolic: swapping x1 <-> x2 alone negates numerator, keeps N.Nt",
             zero(relabel(num, (0, 2, 1, 3)) + num) and zero(relabel(den, (0, 2, 1, 3)) - den))


def make_theta(sign):
    def theta(x):
        x0, x1, x2, x3 = (pt(x, i) for i in range(4))
        e0 = vsub(x2, x1)
        N = cross(vsub(x1, x0), vsub(x2, x0))
        Nt = cross(vsub(x2, x3), vsub(x1, x3))
        return mpmath.atan2(sign * dot(cross(N, Nt), e0) / norm(e0), dot(N, Nt))
    return theta


def main():
    args = hc.parse_args(__doc__, VARIANTS)
    hc.setup()
    rep = hc.Report("proofs.sign-convention", "sign of theta, atan2 form, eq. (12)", args.falsify)
    theta = make_theta(-1 if args.falsify == "sign" else 1)
    symbolic(rep)

    tol = mpf(2) ** -200
    r_form, r_12, r_half = [], [], []
    for lab, x in hc.sample_hinges(11):
        x0, x1, x2, x3 = (pt(x, i) for i in range(4))
        e0, a, b = vsub(x2, x1), vsub(x0, x1), vsub(x1, x3)
        N, Nt = cross(e0, a), cross(e0, b)
        th = theta(x)
        alt = mpmath.atan2(norm(e0) * det3(e0, a, b), dot(N, Nt))
        r_form.append((lab, abs(th - alt) / (1 + abs(alt))))
        n, nt = unit(N), unit(Nt)
        sg = mpmath.sign(det3(n, nt, e0))
        t12 = sg * norm(vsub(n, nt)) / norm(vadd(n, nt))
        r_12.append((lab, abs(mpmath.tan(th / 2) - t12) / (1 + abs(t12))))
        r_half.append((lab, abs(mpmath.sin(abs(th) / 2) - norm(vsub(n, nt)) / 2) +
                       abs(mpmath.cos(th / 2) - norm(vadd(n, nt)) / 2)))
    rep.worst("atan2(((N x Nt).e0)/|e0|, N.Nt) = atan2(|e0| det[e0,a,b], N.Nt)", r_form, tol)
    rep.worst("eq. (12): tan(theta/2) = sgn(det[n,nt,e0]) |n-nt|/|n+nt|", r_12, tol)
    rep.worst("sin(|theta|/2) = |n-nt|/2 and cos(theta/2) = |n+nt|/2", r_half, tol)

    # CONVENTIONS check values
    P = lambda *c: [mpf(v) for v in c]
    x0, x1, x2, x3 = P(0.5, 1, 0), P(0, 0, 0), P(1, 0, 0), P(0.5, -1, 0)
    x = hc.stencil(x0, x1, x2, x3)
    n = unit(cross(vsub(x1, x0), vsub(x2, x0)))
    nt = unit(cross(vsub(x2, x3), vsub(x1, x3)))
    rep.true("check values: theta = 0 and n = nt = (0,0,1)", theta(x) == 0 and n == P(0, 0, 1) and nt == P(0, 0, 1))
    h = mpf(2) ** -60
    g0 = [(theta(hc.stencil(vadd(x0, vscale(h, ek)), x1, x2, x3)) -
           theta(hc.stencil(vsub(x0, vscale(h, ek)), x1, x2, x3))) / (2 * h) for ek in (P(1, 0, 0), P(0, 1, 0), P(0, 0, 1))]
    rep.small("check values: d theta / d x0 = -n/h0 = (0,0,-1) (central difference)", hc.fnorm(vsub(g0, P(0, 0, -1))), mpf(2) ** -100)
    t = mpf("0.25")
    rep.true("lifting x0 along +n makes theta negative (valley)", theta(hc.stencil(vadd(x0, vscale(t, n)), x1, x2, x3)) < 0)
    roof = hc.stencil(P(0.5, 1, -0.25), x1, x2, P(0.5, -1, -0.25))
    r0, r1, r2, r3 = (pt(roof, i) for i in range(4))
    nr, ntr = unit(cross(vsub(r1, r0), vsub(r2, r0))), unit(cross(vsub(r2, r3), vsub(r1, r3)))
    # normals point away from each other: each tilts towards its own apex's side
    away = dot(nr, vsub(r0, r3)) > 0 and dot(ntr, vsub(r3, r0)) > 0
    rep.true("roof with normals pointing away from each other has theta > 0", away and theta(roof) > 0,
             "theta = %s" % mpmath.nstr(theta(roof), 8))
    fold = hc.stencil(x0, x1, x2, x0)
    rep.true("folded flat (x3 = x0): numerator 0, N.Nt < 0, theta = +pi", theta(fold) == +mpmath.pi)
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
