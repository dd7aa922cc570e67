#!/usr/bin/env python3
"""Check for proofs/hessian.md: eq. (6) with the corrected building blocks of eq. (5),
and eq. (3).

1. Eq. (6) (P_1j = omega_1j cos a2 M_j^T, P_2j = omega_2j cos a1 M_j^T, Q~_j = omega~_0j M~_j,
   blocks with rows = components of x_i, completed by H_ji = H_ij^T) against the SymPy
   Hessian of the CONVENTIONS definition (theta_oracle.py), 256 bits, random and hard
   stencils; the oracle itself against 400-bit finite differences at one stencil.
2. The derivation's lemmas: the edge identities
     e^_i / (2A) = omega_{i,i+1} (m_{i+1} + cos a_{i+2} m_i) = -omega_{i,i+2} (m_{i+2} + cos a_{i+1} m_i),
   the gradient of the coefficients f_i = c_i / h_i (c = (-1, cos a2, cos a1)),
     grad_{x_j} f_i = omega_ij c_j m_i + eps_ij m0 / l0^2,  eps = [[0,0,0],[0,-1,1],[0,1,-1]],
   (by 400-bit finite differences of f_i), and the resulting Jacobian of the upper part
   of eq. (4), J_U(i,j) = omega_ij (c_i M_j^T + c_j M_i) + eps_ij N0, with zero row and
   column sums.
3. Eq. (3): Hess psi = psi' Hess theta + psi'' grad theta grad theta^T, for the tan energy
   psi = k a (2 tan(theta/2) - phibar)^2, against SymPy's Hessian of psi(theta(x)).
--falsify printed-P : P_ij = omega_ij cos(alpha_i) M_j^T as printed in eq. (5)
--falsify printed-Qt: Q~_j = omega_0j M~_j as printed (omega of the upper triangle)
--falsify N0-sign  : +N0 and -N0 exchanged in eq. (6)
--falsify transpose: blocks read with rows = components of x_j
"""
import sympy as sp
from mpmath import mp, mpf

import hinge_common as hc
from hinge_common import vsub, vadd, vscale, pt, outer, madd, mscale
import paper_formulas as pf
import theta_oracle as to

VARIANTS = {"printed-P": "P_ij with cos(alpha_i) as printed in eq. (5)",
            "printed-Qt": "Q~_j = omega_0j M~_j as printed in eq. (5)",
            "N0-sign": "N0 and N~0 with the opposite sign in eq. (6)",
            "transpose": "blocks of eq. (6) read with rows = components of x_j"}


def main():
    args = hc.parse_args(__doc__, VARIANTS)
    hc.setup()
    rep = hc.Report("proofs.hessian", "eq. (6) from eq. (4), block by block", args.falsify)
    fz = args.falsify
    oracle = to.ThetaOracle()
    tol = mpf(10) ** -40
    cases = hc.sample_hinges(31)
    res, blocks_worst = [], {}
    for lab, x in cases:
        _, g, H = oracle(x)
        H6 = pf.hessian_eq6(x, P_printed=fz == "printed-P", Qt_printed=fz == "printed-Qt",
                            N0_sign=-1 if fz == "N0-sign" else 1, transpose_rows=fz == "transpose")
        res.append((lab, hc.rel(H6, H)))
        nH = hc.fnorm(H)
        for i in range(4):
            for j in range(4):
                r = hc.fnorm(hc.msub(hc.block(H6, i, j), hc.block(H, i, j))) / nH
                blocks_worst[(i, j)] = max(blocks_worst.get((i, j), 0), r)
    rep.worst("eq. (6) vs SymPy Hessian of the definition", res, tol)
    bad = sorted(k for k, v in blocks_worst.items() if v > tol)
    rep.true("every 3x3 block H_ij of eq. (6) agrees", not bad, "blocks off: %s" % bad if bad else "16 of 16")

    # the oracle against 400-bit finite differences of the bare definition
    lab, x = cases[1]
    _, _, H = oracle(x)
    mp.prec = 400
    Hf = to.fd_hessian(to.theta_direct, x, mpf(10) ** -22)
    mp.prec = hc.PREC_BITS
    rep.small("oracle Hessian vs 400-bit finite differences [%s]" % lab, hc.rel(H, Hf), mpf(10) ** -60)

    # lemmas of hessian.md, upper triangle of each stencil (and the lower one in its own labels)
    r_edge, r_df, r_J, r_sums = [], [], [], []
    for lab, x in cases[:4] + cases[-7:-6]:
        for tri_pts in ((pt(x, 0), pt(x, 1), pt(x, 2)), (pt(x, 3), pt(x, 2), pt(x, 1))):
            T = pf.Tri(*tri_pts)
            c = pf.c_coef(T)
            for i in range(3):
                i1, i2 = (i + 1) % 3, (i + 2) % 3
                lhs = vscale(1 / (2 * T.A), T.eh[i])
                r1 = vscale(T.omega(i, i1), vadd(T.m[i1], vscale(T.cos[i2], T.m[i])))
                r2 = vscale(-T.omega(i, i2), vadd(T.m[i2], vscale(T.cos[i1], T.m[i])))
                r_edge.append((lab, (hc.fnorm(vsub(lhs, r1)) + hc.fnorm(vsub(lhs, r2))) / hc.fnorm(lhs)))
            mp.prec = 400
            y = hc.stencil(*tri_pts)

            def fvec(yy):
                Ty = pf.Tri(pt(yy, 0), pt(yy, 1), pt(yy, 2))
                cy = pf.c_coef(Ty)
                return [cy[i] / Ty.h[i] for i in range(3)]

            def gU(yy):
                Ty = pf.Tri(pt(yy, 0), pt(yy, 1), pt(yy, 2))
                cy = pf.c_coef(Ty)
                return sum((vscale(cy[i] / Ty.h[i], Ty.n) for i in range(3)), [])
            Jf = to.fd_jacobian(fvec, y, mpf(10) ** -24)
            JU = to.fd_jacobian(gU, y, mpf(10) ** -24)
            mp.prec = hc.PREC_BITS
            l0sq = T.l[0] ** 2
            for i in range(3):
                for j in range(3):
                    claim = vadd(vscale(T.omega(i, j) * c[j], T.m[i]), vscale(mpf(pf.EPS[i][j]) / l0sq, T.m[0]))
                    got = Jf[i][3 * j:3 * j + 3]
                    r_df.append((lab, hc.fnorm(vsub(got, claim)) / hc.fnorm(Jf)))
            Jc = hc.from_blocks({(i, j): pf.J_unified(T, i, j) for i in range(3) for j in range(3)}, nb=3)
            r_J.append((lab, hc.rel(Jc, JU)))
            rs = max(hc.fnorm(madd(*[pf.J_unified(T, i, j) for j in range(3)])) for i in range(3))
            cs = max(hc.fnorm(madd(*[pf.J_unified(T, i, j) for i in range(3)])) for j in range(3))
            r_sums.append((lab, (rs + cs) / hc.fnorm(Jc)))
    rep.worst("lemma: edge identities e^_i/(2A) = omega (m + cos m) (two forms)", r_edge, tol)
    rep.worst("lemma: grad_xj (c_i/h_i) = omega_ij c_j m_i + eps_ij m0/l0^2", r_df, mpf(10) ** -60)
    rep.worst("J_U = omega_ij (c_i M_j^T + c_j M_i) + eps_ij N0 (vs differences of (4))", r_J, mpf(10) ** -60)
    rep.worst("J_U has zero block row sums and zero block column sums", r_sums, tol)

    # eq. (3) with the tan energy
    th = sp.Symbol("theta")
    # k = 0.7, a = 1.9, phibar = 0.3
    psi = sp.Rational(7, 10) * sp.Rational(19, 10) * (2 * sp.tan(th / 2) - sp.Rational(3, 10)) ** 2
    eo = to.ThetaOracle(psi=psi, theta_symbol=th)
    r3 = []
    for lab, x in cases[:6]:
        t, g, H = oracle(x)
        _, _, He = eo(x)
        d1 = sp.lambdify(th, sp.diff(psi, th), "mpmath")(t)
        d2 = sp.lambdify(th, sp.diff(psi, th, 2), "mpmath")(t)
        g4 = pf.gradient_eq4(x)
        H6 = pf.hessian_eq6(x, P_printed=fz == "printed-P", Qt_printed=fz == "printed-Qt",
                            N0_sign=-1 if fz == "N0-sign" else 1, transpose_rows=fz == "transpose")
        Hpsi = madd(mscale(d1, H6), mscale(d2, outer(g4, g4)))
        r3.append((lab, hc.rel(Hpsi, He)))
    rep.worst("eq. (3): psi' (6) + psi'' (4)(4)^T vs SymPy Hessian of psi(theta)", r3, tol)
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
