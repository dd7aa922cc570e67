#!/usr/bin/env python3
"""Check for proofs/triangle-hessian.md: the per-triangle Hessian of eq. (7) and its
conditional transpose, assembled over small meshes.

Meshes: a perturbed octahedron (closed: every edge is a hinge) and a perturbed
hexagonal fan (six hinges, six boundary edges with sigma = 0).  Every hinge k gets its own
energy psi_k(theta) = k_k (theta - tb_k)^2 + b_k (2 tan(theta/2) - pb_k)^2.

1. Threefold symmetry: in each triangle, the sum over its three edges of c_k times the left
   column of (6) (the unified half-hinge form, hessian.md) relabelled to edge k equals
   eq. (7) with d_i = c_{i-1} cos a_{i+1} + c_{i+1} cos a_{i-1} - c_i, R_i = c_i N_i (no transposes).
2. Assembly: sum over triangles of H^Delta (eq. (7)) + sum over hinges of psi'' grad grad^T
   (eq. (4)) equals sum over hinges of psi' Hess theta + psi'' grad grad^T with Hess theta and
   grad theta from the SymPy oracle (eq. (3) is checked in check_hessian.py), when the dagger
   transposes R for exactly one of the two faces of every interior edge: both the paper's rule
   ("mesh edge counter-clockwise with respect to the triangle", edges oriented from the lower
   to the higher vertex index) and the opposite rule work; transposing in neither or both
   faces does not.  The gradient sum psi' grad theta is checked too.
--falsify neither: the dagger never transposes
--falsify both   : the dagger always transposes
"""
import random

import mpmath
from mpmath import mpf

import hinge_common as hc
from hinge_common import madd, mscale, msub
import paper_formulas as pf
import theta_oracle as to

VARIANTS = {"neither": "the dagger never transposes R_i", "both": "the dagger always transposes R_i"}


def octahedron(rng):
    V = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]]
    V = [[mpf(c) + mpf(rng.uniform(-0.2, 0.2)) for c in v] for v in V]
    F = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    return V, F


def fan(rng):
    V = [[mpf(rng.uniform(-0.1, 0.1)), mpf(rng.uniform(-0.1, 0.1)), mpf(rng.uniform(-0.3, 0.3))]]
    for k in range(6):
        ang = 2 * mpmath.pi * k / 6 + mpf(rng.uniform(-0.2, 0.2))
        r = mpf(rng.uniform(0.8, 1.2))
        V.append([r * mpmath.cos(ang), r * mpmath.sin(ang), mpf(rng.uniform(-0.5, 0.5))])
    F = [(0, 1 + k, 1 + (k + 1) % 6) for k in range(6)]
    return V, F


def hinges(F):
    """Interior edges: {(a, b) with a -> b in the upper face: (x0, x1=a, x2=b, x3)}."""
    directed = {}
    for f in F:
        for i in range(3):
            directed[(f[(i + 1) % 3], f[(i + 2) % 3])] = f[i]
    out = {}
    for (a, b), apex in directed.items():
        if (b, a) in directed and a < b:
            out[(a, b)] = (apex, a, b, directed[(b, a)])
    return out


def run_mesh(rep_rows, name, V, F, oracle, rng, rule):
    n = 3 * len(V)
    H = hinges(F)
    psi = {}
    for e in H:
        kk, tb, bb, pb = (mpf(rng.uniform(0.5, 2)), mpf(rng.uniform(-1, 1)),
                          mpf(rng.uniform(0.1, 1)), mpf(rng.uniform(-1, 1)))
        psi[e] = (kk, tb, bb, pb)

    def dpsi(e, t):
        kk, tb, bb, pb = psi[e]
        s = 1 / mpmath.cos(t / 2) ** 2        # d/dtheta 2 tan(theta/2)
        u = 2 * mpmath.tan(t / 2) - pb
        d1 = 2 * kk * (t - tb) + 2 * bb * u * s
        d2 = 2 * kk + 2 * bb * (s * s + u * s * mpmath.tan(t / 2))
        return d1, d2

    ref_H, ref_g = hc.zeros(n), [mpf(0)] * n
    eq_H, eq_g = hc.zeros(n), [mpf(0)] * n
    c_of = {}
    for e, quad in H.items():
        x = hc.stencil(*[V[v] for v in quad])
        t, g, Hth = oracle(x)
        d1, d2 = dpsi(e, t)
        c_of[e] = d1
        g4 = pf.gradient_eq4(x)
        for p in range(4):
            for q in range(4):
                for a in range(3):
                    for b in range(3):
                        I, J = 3 * quad[p] + a, 3 * quad[q] + b
                        ref_H[I][J] += d1 * Hth[3 * p + a][3 * q + b] + d2 * g[3 * p + a] * g[3 * q + b]
                        eq_H[I][J] += d2 * g4[3 * p + a] * g4[3 * q + b]
            for a in range(3):
                ref_g[3 * quad[p] + a] += d1 * g[3 * p + a]
                eq_g[3 * quad[p] + a] += d1 * g4[3 * p + a]
    r_sym = []
    for f in F:
        T = pf.Tri(*[V[v] for v in f])
        c, dag = [], []
        for i in range(3):
            a, b = f[(i + 1) % 3], f[(i + 2) % 3]
            key = (min(a, b), max(a, b))
            c.append(c_of.get(key, mpf(0)))               # sigma_i = 0 on the boundary
            ccw = a < b                                   # global edge min->max runs a->b: CCW in this face
            dag.append({"paper": ccw, "opposite": not ccw, "neither": False, "both": True}[rule])
        B = pf.triangle_hessian_eq7(T, c, dag)
        # threefold symmetry: sum of three relabelled, scaled half-hinges (no transposes)
        S = {}
        for k in range(3):
            lab = [k, (k + 1) % 3, (k + 2) % 3]
            Tk = pf.Tri(*[V[f[v]] for v in lab])
            for (i, j), A in pf.half_hinge_blocks(Tk).items():
                key = (lab[i], lab[j])
                S[key] = madd(S[key], mscale(c[k], A)) if key in S else mscale(c[k], A)
        B0 = pf.triangle_hessian_eq7(T, c, [False] * 3)
        r_sym.append(max(hc.fnorm(msub(B0[k], S[k])) for k in B0) /
                     max(hc.fnorm(S[k]) for k in S))
        for (i, j), A in B.items():
            for a in range(3):
                for b in range(3):
                    eq_H[3 * f[i] + a][3 * f[j] + b] += A[a][b]
    rep_rows.append((name, rule, hc.rel(eq_H, ref_H), hc.rel(eq_g, ref_g), max(r_sym), len(H), len(F)))


def main():
    args = hc.parse_args(__doc__, VARIANTS)
    hc.setup()
    rep = hc.Report("proofs.triangle-hessian", "eq. (7), threefold symmetry and the conditional transpose",
                    args.falsify)
    bare = to.ThetaOracle()
    memo = {}

    def oracle(x):          # the same hinges are evaluated once for all dagger rules
        key = tuple(x)
        if key not in memo:
            memo[key] = bare(x)
        return memo[key]
    tol = mpf(10) ** -40
    rows = []
    claimed = [args.falsify] if args.falsify else ["paper", "opposite"]
    wrong = [r for r in ("paper", "opposite", "neither", "both") if r not in claimed]
    for seed, (name, mk) in enumerate((("octahedron", octahedron), ("hexagonal fan", fan))):
        for rule in claimed + wrong:
            rng = random.Random(100 + seed)
            V, F = mk(rng)
            run_mesh(rows, name, V, F, oracle, rng, rule)
    for name, rule, rH, rg, rs, nh, nf in rows:
        print("  mesh %-13s (%d faces, %d hinges) dagger=%-8s |H - ref|/|ref| = %s" %
              (name, nf, nh, rule, mpmath.nstr(rH, 3)))
    rep.worst("threefold symmetry: eq. (7) = sum of 3 scaled half-hinges", [(r[0], r[4]) for r in rows], tol)
    rep.worst("sum psi' grad theta: eq. (4) assembled = oracle", [(r[0], r[3]) for r in rows], tol)
    rep.worst("eq. (7) + psi'' grad grad^T = energy Hessian, dagger as claimed (%s)" % "/".join(claimed),
              [("%s, %s" % (r[0], r[1]), r[2]) for r in rows if r[1] in claimed], tol)
    rep.large("other dagger choices (%s) give a wrong Hessian (smallest error)" % "/".join(wrong),
              min(r[2] for r in rows if r[1] in wrong), mpf("1e-6"))
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
