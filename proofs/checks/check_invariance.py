#!/usr/bin/env python3
"""Check for proofs/invariance.md: rigid motions, reflections and scaling; the null space,
rank and inertia of Hess theta.  All derivatives from the SymPy oracle (theta_oracle.py).

1. theta(R x + t) = theta(x), grad -> (I (x) R) grad, Hess -> (I (x) R) Hess (I (x) R)^T for
   proper rotations R; a reflection Q negates all three (theta -> -theta); x -> s x leaves
   theta unchanged, grad -> grad / s, Hess -> Hess / s^2.
2. Hess theta annihilates the three translations and the stretch along the hinge,
   xi = (e^0 (e^0 . x_j))_j; Hess x = -grad (scaling); for a rotation generator
   rho_w = (w x x_j)_j, Hess rho_w = (w x grad_xj)_j, which is NOT zero unless every grad_xj
   is parallel to w (possible only for theta in {0, pi}, with w || n).
3. For theta not in {0, pi}: rank 8, null space = span(translations, xi), inertia (4+, 4-, 4 zero).
   At theta = 0 (flat) and theta = pi (folded): rank 6, inertia (3+, 3-, 6 zero), the extra null
   vectors being rho_n and the in-plane shear along the hinge (e^0 (m . x_j))_j.
--falsify rotation-null: claim Hess rho_w = 0 (rotations in the null space)
--falsify scale        : claim Hess(s x) = Hess(x) / s
"""
import random

import mpmath
from mpmath import mp, mpf

import hinge_common as hc
from hinge_common import vsub, vadd, vscale, dot, cross, norm, unit, pt, matvec, matmul, mT
import paper_formulas as pf
import theta_oracle as to

VARIANTS = {"rotation-null": "Hess theta annihilates rotation generators",
            "scale": "Hess theta scales like 1/s instead of 1/s^2"}


def kron_rot(R):
    K = hc.zeros(12)
    for b in range(4):
        for i in range(3):
            for j in range(3):
                K[3 * b + i][3 * b + j] = R[i][j]
    return K


def apply_affine(x, R, t, s=1):
    return hc.stencil(*[vadd(vscale(s, matvec(R, pt(x, j))), t) for j in range(4)])


def per_vertex(f, x):
    return hc.stencil(*[f(pt(x, j)) for j in range(4)])


def eig_counts(H):
    E, _ = mp.eigsy(mp.matrix(H))
    ev = [E[i] for i in range(12)]
    sc = max(abs(v) for v in ev)
    thr = sc * mpf(10) ** -30
    pos = sum(1 for v in ev if v > thr)
    neg = sum(1 for v in ev if v < -thr)
    gap = min(abs(v) for v in ev if abs(v) > thr) / sc
    return pos, neg, 12 - pos - neg, gap


def main():
    args = hc.parse_args(__doc__, VARIANTS)
    hc.setup()
    rep = hc.Report("proofs.invariance", "rigid motion, reflection, scale; null space and inertia", args.falsify)
    oracle = to.ThetaOracle()
    tol = mpf(10) ** -40
    rng = random.Random(61)
    cases = hc.sample_hinges(61, n_generic=3)
    rr = {k: [] for k in ("rot", "refl", "scale", "trans", "xi", "sx", "rho", "rhoflat", "null", "inertia")}
    rho_size = []
    for lab, x in cases:
        th, g, H = oracle(x)
        nH = hc.fnorm(H)
        R = hc.rand_rotation(rng)
        size = norm(vsub(pt(x, 2), pt(x, 1)))
        t = [size * mpf(rng.uniform(-5, 5)) for _ in range(3)]   # the oracle expands polynomials:
        # a translation far beyond the stencil's size would only measure its cancellation
        th2, g2, H2 = oracle(apply_affine(x, R, t))
        K = kron_rot(R)
        rr["rot"].append((lab, abs(th2 - th) + hc.rel(g2, matvec(K, g)) + hc.rel(H2, matmul(matmul(K, H), mT(K)))))
        Qm = [[mpf(-1), 0, 0], [0, mpf(1), 0], [0, 0, mpf(1)]]
        Qm = matmul(R, Qm)
        th3, g3, H3 = oracle(apply_affine(x, Qm, t))
        KQ = kron_rot(Qm)
        wrap = min(abs(th3 + th), abs(abs(th3 + th) - 2 * mpmath.pi))   # +-pi branch
        rr["refl"].append((lab, wrap + hc.rel(g3, hc.vscale(-1, matvec(KQ, g))) +
                           hc.rel(H3, hc.mscale(-1, matmul(matmul(KQ, H), mT(KQ))))))
        s = mpf(rng.choice([1e-3, 7.5, 1e4]))
        th4, g4, H4 = oracle(apply_affine(x, [[1, 0, 0], [0, 1, 0], [0, 0, 1]], t, s))
        hexp = 1 if args.falsify == "scale" else 2
        rr["scale"].append((lab, abs(th4 - th) + hc.rel(g4, vscale(1 / s, g)) + hc.rel(H4, hc.mscale(s ** -hexp, H))))
        # null vectors
        T = pf.upper(x)
        e = T.eh[0]
        base = pt(x, 1)
        xs = per_vertex(lambda p: vsub(p, base), x)        # positions relative to x1
        for k in range(3):
            tau = [mpf(1) if i % 3 == k else mpf(0) for i in range(12)]
            rr["trans"].append((lab, hc.fnorm(matvec(H, tau)) / (nH * 2)))
        xi = per_vertex(lambda p: vscale(dot(e, p), e), xs)
        rr["xi"].append((lab, hc.fnorm(matvec(H, xi)) / (nH * hc.fnorm(xi))))
        rr["sx"].append((lab, hc.rel(matvec(H, xs), vscale(-1, g))))
        w = unit([mpf(rng.gauss(0, 1)) for _ in range(3)])
        rho = per_vertex(lambda p: cross(w, p), xs)
        Hr = matvec(H, rho)
        claim = [mpf(0)] * 12 if args.falsify == "rotation-null" else per_vertex(lambda gj: cross(w, gj), g)
        rr["rho"].append((lab, hc.fnorm(hc.vsub(Hr[:3], claim[:3]) + hc.vsub(Hr[3:6], claim[3:6]) +
                                           hc.vsub(Hr[6:9], claim[6:9]) + hc.vsub(Hr[9:], claim[9:])) /
                          (nH * hc.fnorm(rho))))
        rho_size.append((lab, hc.fnorm(Hr) / (nH * hc.fnorm(rho))))
        pos, neg, zero, gap = eig_counts(H)
        rr["inertia"].append((lab, (pos, neg, zero), gap))
    rep.worst("rotation + translation: theta, R grad, R Hess R^T", rr["rot"], tol)
    rep.worst("reflection: -theta, -Q grad, -Q Hess Q^T", rr["refl"], tol)
    rep.worst("scaling x -> s x: theta, grad/s, Hess/s^%d" % (1 if args.falsify == "scale" else 2), rr["scale"], tol)
    rep.worst("Hess . translation = 0 (3 directions)", rr["trans"], tol)
    rep.worst("Hess . xi = 0, xi = stretch along the hinge (e^0 (e^0 . x_j))", rr["xi"], tol)
    rep.worst("Hess . x = -grad (scaling direction)", rr["sx"], tol)
    rep.worst("Hess . rho_w = %s" % ("0 (rotations in the null space)" if args.falsify == "rotation-null"
                                      else "(w x grad_xj)_j"), rr["rho"], tol)
    rep.large("... and Hess . rho_w != 0 for random w (smallest |H rho|/(|H||rho|))",
              min(v for _, v in rho_size), mpf(10) ** -12)
    bad = [(l, c) for l, c, _ in rr["inertia"] if c != (4, 4, 4)]
    rep.true("inertia (4+, 4-, 4 zero) at every stencil with theta not in {0, pi}", not bad,
             "%d stencils, smallest nonzero |eigenvalue|/max = %s" % (len(rr["inertia"]),
                                                                       mpmath.nstr(min(gp for _, _, gp in rr["inertia"]), 3))
             if not bad else str(bad))
    # theta = 0 and theta = pi exactly
    for tag, beta in (("flat theta = 0", mpf(0)), ("folded theta = pi", mpmath.pi)):
        x = hc.make_hinge(mpf("1.1"), mpf("0.3"), mpf("0.8"), mpf("0.7"), mpf("0.6"), beta,
                          R=hc.rand_rotation(rng), offset=(0.25, -0.5, 1))
        th, g, H = oracle(x)
        nH = hc.fnorm(H)
        pos, neg, zero, gap = eig_counts(H)
        rep.true("%s: inertia (3+, 3-, 6 zero)" % tag, (pos, neg, zero) == (3, 3, 6), str((pos, neg, zero)))
        T = pf.upper(x)
        base = pt(x, 1)
        xs = per_vertex(lambda p: vsub(p, base), x)
        rho_n = per_vertex(lambda p: cross(T.n, p), xs)
        shear = per_vertex(lambda p: vscale(dot(T.m[0], p), T.eh[0]), xs)
        r = (hc.fnorm(matvec(H, rho_n)) / hc.fnorm(rho_n) + hc.fnorm(matvec(H, shear)) / hc.fnorm(shear)) / nH
        rep.small("%s: Hess rho_n = 0 and Hess (e^0 (m0 . x_j)) = 0" % tag, r, tol)
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
