#!/usr/bin/env python3
"""Check for proofs/edge-collapse.md: what happens as the hinge edge collapses (section 8).

Collapse: x0, x3 and a point p fixed, x1 = p + eps*sig*u, x2 = p + eps*(sig+1)*u (unit u fixed),
so e0 = eps*u, l0 = eps -> 0.  Write T* for the stencil (x0, p, p+u, x3) (unit hinge edge on the
same line) and G, K for its gradient block g_2 and Hessian block H_22 (= the gradient and Hessian
of e -> theta(x0, p, p+e, x3) at e = u).  Claims (derived in edge-collapse.md):
  1. theta(eps) = theta(T*) for every eps (no limit needed), but theta has no limit at the collapsed
     configuration itself: it depends on the direction u.
  2. grad_x0, grad_x3 are constant in eps (= those of T*);
     l0 grad_x1 = -G + O(eps), l0 grad_x2 = +G + O(eps): the gradient blows up like 1/l0 unless G = 0,
     and G = 0 iff u . (x0 - p) = 0 and u . (x3 - p) = 0 (the "kite"), for theta not in {0, pi};
     G = (u.a0)/|u x a0| n + (u.b0)/|u x b0| nt, a0 = x0 - p, b0 = x3 - p, n = u x a0/|u x a0|,
     nt = u x (-b0)/|u x b0|.
  3. l0^2 Hess -> [[0,0,0,0],[0,K,-K,0],[0,-K,K,0],[0,0,0,0]] at rate O(eps): the Hessian blows up like
     1/l0^2 unless K = 0; at a kite the gradient stays bounded but K != 0 (Hessian still ~ 1/l0^2).
All derivatives from the SymPy oracle at 384 bits; rates checked by the ratio of errors between
eps = 1e-6 and eps = 1e-8 (must be ~1e-2 for O(eps)).
--falsify paper: claim that grad and Hess have finite limits (stay bounded as l0 -> 0)
"""
import random

import mpmath
from mpmath import mpf

import hinge_common as hc
from hinge_common import vsub, vadd, vscale, dot, cross, norm, unit
import theta_oracle as to

VARIANTS = {"paper": "grad theta and Hess theta stay bounded as the hinge edge collapses"}


def collapse(x0, x3, p, u, sig, eps):
    return hc.stencil(x0, vadd(p, vscale(eps * sig, u)), vadd(p, vscale(eps * (sig + 1), u)), x3)


def main():
    args = hc.parse_args(__doc__, VARIANTS)
    hc.setup(384)
    rep = hc.Report("proofs.edge-collapse", "limits as the hinge edge length -> 0 (section 8)", args.falsify)
    oracle = to.ThetaOracle()
    rng = random.Random(71)
    tol = mpf(10) ** -50
    epss = [mpf(10) ** -k for k in (2, 4, 6, 8)]
    configs = []
    for k in range(3):
        x0 = [mpf(rng.uniform(-1, 1)) for _ in range(3)]
        x3 = [mpf(rng.uniform(-1, 1)) for _ in range(3)]
        p = [mpf(rng.uniform(-0.2, 0.2)) for _ in range(3)]
        u = unit([mpf(rng.gauss(0, 1)) for _ in range(3)])
        configs.append(("generic-%d" % k, x0, x3, p, u, mpf(rng.uniform(-1, 0.5))))
    # kite: u orthogonal to x0 - p and x3 - p
    p = [mpf(0)] * 3
    x0, x3 = [mpf("0.9"), mpf("0.2"), mpf("0.1")], [mpf("-0.3"), mpf("-0.8"), mpf("0.5")]
    u = unit(cross(x0, x3))
    configs.append(("kite", x0, x3, p, u, mpf("-0.5")))

    r_theta, r_03, r_G, r_Gf, r_K, rates_g, rates_H, sizes, kite = [], [], [], [], [], [], [], [], None
    bounded = []
    for lab, x0, x3, p, u, sig in configs:
        Ts = hc.stencil(x0, p, vadd(p, u), x3)
        th_s, g_s, H_s = oracle(Ts)
        G = g_s[6:9]
        K = hc.block(H_s, 2, 2)
        a0, b0 = vsub(x0, p), vsub(x3, p)
        n, nt = unit(cross(u, a0)), unit(cross(u, vsub(p, x3)))   # N = e0 x (x0-x1), Nt = e0 x (x1-x3)
        Gf = vadd(vscale(dot(u, a0) / norm(cross(u, a0)), n), vscale(dot(u, b0) / norm(cross(u, b0)), nt))
        r_Gf.append((lab, hc.fnorm(vsub(G, Gf)) / max(hc.fnorm(g_s), 1)))
        pattern = hc.from_blocks({(1, 1): K, (2, 2): K, (1, 2): hc.mscale(-1, K), (2, 1): hc.mscale(-1, K)})
        lim_g = [mpf(0)] * 3 + vscale(-1, G) + G + [mpf(0)] * 3
        errs_g, errs_H, norms_g, norms_H = [], [], [], []
        for eps in epss:
            x = collapse(x0, x3, p, u, sig, eps)
            th, g, H = oracle(x)
            r_theta.append((lab, abs(th - th_s)))
            r_03.append((lab, hc.fnorm(vsub(g[0:3], g_s[0:3])) + hc.fnorm(vsub(g[9:12], g_s[9:12]))))
            errs_g.append(hc.fnorm([eps * gi - li for gi, li in zip(g, lim_g)]))
            errs_H.append(hc.fnorm(hc.msub(hc.mscale(eps ** 2, H), pattern)))
            norms_g.append(hc.fnorm(g)); norms_H.append(hc.fnorm(H))
        if lab == "kite":
            kite = (hc.fnorm(G), hc.fnorm(K), norms_g, norms_H)
        else:
            sizes.append((lab, min(hc.fnorm(G), hc.fnorm(K))))
            r_G.append((lab, errs_g[-1] / epss[-1]))           # error / eps stays O(1)
            rates_g.append((lab, errs_g[-1] / errs_g[-2]))
            rates_H.append((lab, errs_H[-1] / errs_H[-2]))
            r_K.append((lab, errs_H[-1] / hc.fnorm(K)))
        bounded.append((lab, norms_g[-1] / norms_g[0], norms_H[-1] / norms_H[0]))
        print("  %-10s |G| = %s |K| = %s   eps: %s   |grad|: %s   |Hess|: %s" % (
            lab, mpmath.nstr(hc.fnorm(G), 3), mpmath.nstr(hc.fnorm(K), 3), [mpmath.nstr(e, 1) for e in epss],
            [mpmath.nstr(v, 3) for v in norms_g], [mpmath.nstr(v, 3) for v in norms_H]))
    rep.worst("theta(eps) = theta(T*) exactly along the collapse", r_theta, tol)
    # no limit at the collapsed point: two directions through the same p give different theta
    lab, x0, x3, p, u, sig = configs[0]
    u2 = unit(vadd(u, [mpf("0.3"), mpf("-0.2"), mpf("0.1")]))
    t1 = oracle(collapse(x0, x3, p, u, sig, epss[-1]), want_hess=False)[0]
    t2 = oracle(collapse(x0, x3, p, u2, sig, epss[-1]), want_hess=False)[0]
    rep.large("theta at l0 = 1e-8 depends on the direction u (no limit at l0 = 0)", abs(t1 - t2), mpf("1e-3"))
    rep.worst("grad_x0, grad_x3 constant along the collapse (= those of T*)", r_03, tol)
    rep.worst("G = (u.a0)/|u x a0| n + (u.b0)/|u x b0| nt", r_Gf, tol)
    if args.falsify == "paper":
        rep.small("grad bounded: max |grad(1e-8)| / |grad(1e-2)| (paper: finite limit)",
                  max(b[1] for b in bounded), mpf(2))
        rep.small("Hess bounded: max |Hess(1e-8)| / |Hess(1e-2)| (paper: finite limit)",
                  max(b[2] for b in bounded), mpf(2))
    else:
        rep.large("generic collapse: G != 0 and K != 0 (smallest norm)", min(s for _, s in sizes), mpf("1e-3"))
        rep.worst("|l0 grad - (0, -G, G, 0)| / l0 = O(1) at l0 = 1e-8", r_G, mpf(100))
        rep.worst("l0 grad converges at O(l0): error ratio 1e-6 -> 1e-8 ~ 1e-2", rates_g, mpf("0.02"))
        rep.worst("l0^2 Hess converges at O(l0): error ratio 1e-6 -> 1e-8 ~ 1e-2", rates_H, mpf("0.02"))
        rep.worst("l0^2 Hess -> K pattern: error at l0 = 1e-8 relative to |K|", r_K, mpf("1e-6"))
        Gk, Kk, ng, nH = kite
        rep.small("kite: G = 0", Gk, tol)
        rep.small("kite: grad bounded (|grad(1e-8)| / |grad(1e-2)| - 1)", abs(ng[-1] / ng[0] - 1), mpf("0.1"))
        rep.large("kite: K != 0, Hess still grows like 1/l0^2 (|Hess| l0^2 at 1e-8)", nH[-1] * epss[-1] ** 2, mpf("1e-3"))
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
