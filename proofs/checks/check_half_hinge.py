#!/usr/bin/env python3
"""Check for proofs/half-hinge.md: the split of Hess theta into upper and lower
contributions, and the transpose of N0 in exactly one of the two half-hinges.

1. J_U = Jacobian of the upper part of eq. (4), g_U = (-n/h0, cos a2/h1 n, cos a1/h2 n),
   by 400-bit finite differences of the literal formula, equals
   J_U(i,j) = omega_ij (c_i M_j^T + c_j M_i) + eps_ij N0; in particular
   J_U(1,2) = P12 + P21^T + N0, J_U(2,1) = P21 + P12^T + N0, and J_U is NOT symmetric:
   J_U(2,1) - J_U(1,2)^T = N0 - N0^T = -[e^0]_x / l0^2.
2. J_L (lower part of eq. (4)) equals the same formula for the lower triangle in its own
   counter-clockwise labels (x3, x2, x1), i.e. the right column of eq. (6) in tilde labels.
3. J_U + J_L = Hess theta (SymPy oracle); N~0 - N~0^T = +[e^0]_x / l0^2, so N0 + N~0 is symmetric.
4. Each half-hinge computed from the left column of eq. (6) in its own labels, blocks
   (0,0),(1,1),(2,2),(1,0),(2,0),(1,2) completed by symmetry: the sum is Hess theta iff N0 is
   transposed in exactly one of the two (either one); transposing in neither or both is
   off by exactly +-[e^0]_x / l0^2 in the blocks (1,2), (2,1).
5. Reversing e0 (relabelling (x0,x1,x2,x3) -> (x3,x2,x1,x0)) transposes N0 and N~0 in H_12:
   H_12 = P12 + P21^T + N0^T + P~12 + P~21^T + N~0^T as well.
--falsify neither: N0 un-transposed in both half-hinges is claimed to give Hess theta
--falsify both   : N0 transposed in both half-hinges is claimed to give Hess theta
"""
from mpmath import mp, mpf

import hinge_common as hc
from hinge_common import pt, madd, mscale, mT, msub, skew
import paper_formulas as pf
import theta_oracle as to

VARIANTS = {"neither": "no half-hinge transposes N0", "both": "both half-hinges transpose N0"}


def embed(local_blocks, vmap):
    return hc.from_blocks({(vmap[i], vmap[j]): A for (i, j), A in local_blocks.items()})


def main():
    args = hc.parse_args(__doc__, VARIANTS)
    hc.setup()
    rep = hc.Report("proofs.half-hinge", "half-hinges and the transpose of N0", args.falsify)
    oracle = to.ThetaOracle()
    tol, tolfd = mpf(10) ** -40, mpf(10) ** -60
    cases = hc.sample_hinges(41, n_generic=6)
    r = {k: [] for k in ("JU", "JU12", "asym", "JL", "sum", "Nsym", "Nt", "one", "rev")}
    offs = []
    for lab, x in cases:
        _, _, H = oracle(x)
        T, L = pf.upper(x), pf.lower(x)
        l0 = T.l[0]
        E = mscale(1 / l0 ** 2, skew(T.eh[0]))
        nH = hc.fnorm(H)
        mp.prec = 400
        step = mpf(10) ** -24 * min(T.h + L.h)
        JU = to.fd_jacobian(pf.gradient_upper_part, x, step)   # 9 x 12, rows x0,x1,x2
        JL = to.fd_jacobian(pf.gradient_lower_part, x, step)   # 9 x 12, rows x1,x2,x3
        mp.prec = hc.PREC_BITS
        def blk(J, i, j):
            return [J[3 * i + a][3 * j:3 * j + 3] for a in range(3)]
        JUc = {(i, j): pf.J_unified(T, i, j) for i in range(3) for j in range(3)}
        r["JU"].append((lab, max(hc.rel(blk(JU, i, j), JUc[(i, j)]) if hc.fnorm(JUc[(i, j)]) else 0
                                for i in range(3) for j in range(3))))
        P = lambda i, j: pf.P(T, i, j)
        c12 = madd(P(1, 2), mT(P(2, 1)), T.N[0])
        c21 = madd(P(2, 1), mT(P(1, 2)), T.N[0])
        r["JU12"].append((lab, max(hc.rel(blk(JU, 1, 2), c12), hc.rel(blk(JU, 2, 1), c21))))
        asym = msub(blk(JU, 2, 1), mT(blk(JU, 1, 2)))
        r["asym"].append((lab, hc.rel(asym, mscale(-1, E))))
        # lower: own CCW labels (x3, x2, x1) -> global (3, 2, 1); tilde labels (x3, x1, x2)
        Lo = pf.Tri(pt(x, 3), pt(x, 2), pt(x, 1))
        gmap = {0: 3, 1: 2, 2: 1}
        rowmap = {1: 0, 2: 1, 3: 2}
        worst = 0
        for i in range(3):
            for j in range(3):
                A = pf.J_unified(Lo, i, j)
                gi, gj = gmap[i], gmap[j]
                worst = max(worst, hc.fnorm(msub(blk(JL, rowmap[gi], gj), A)) / nH)
        Pt = lambda i, j: pf.P(L, i, j)
        tilde12 = madd(Pt(1, 2), mT(Pt(2, 1)), L.N[0])
        worst = max(worst, hc.rel(blk(JL, 0, 2), tilde12))
        r["JL"].append((lab, worst))
        Jsum = hc.zeros(12)
        for a in range(9):
            for b in range(12):
                Jsum[a][b] += JU[a][b]
                Jsum[a + 3][b] += JL[a][b]
        r["sum"].append((lab, hc.rel(Jsum, H)))
        S = madd(T.N[0], L.N[0])
        r["Nsym"].append((lab, hc.fnorm(msub(S, mT(S))) * l0 ** 2))
        r["Nt"].append((lab, hc.rel(msub(L.N[0], mT(L.N[0])), E)))
        # half-hinge assembly
        Tu = pf.Tri(pt(x, 0), pt(x, 1), pt(x, 2))
        for tu, tl in ((False, False), (True, False), (False, True), (True, True)):
            Hh = madd(embed(pf.half_hinge_blocks(Tu, tu), {0: 0, 1: 1, 2: 2}),
                      embed(pf.half_hinge_blocks(Lo, tl), gmap))
            d = hc.rel(Hh, H)
            claimed_ok = (tu != tl) if not args.falsify else ((tu, tl) == ((False, False) if args.falsify == "neither" else (True, True)))
            if claimed_ok:
                r["one"].append(("%s transpose upper=%s lower=%s" % (lab, tu, tl), d))
            else:
                s = 1 if (tu, tl) == (False, False) else -1
                D = msub(Hh, H)
                pattern = hc.from_blocks({(1, 2): mscale(-s, E), (2, 1): mscale(s, E)})
                exact = hc.rel(D, pattern) if hc.fnorm(D) else mpf(1)
                offs.append(("%s upper=%s lower=%s" % (lab, tu, tl), hc.fnorm(D) * l0 ** 2 / 2, exact))
        # reversing e0 transposes N0 and N~0 in H_12
        rev = madd(P(1, 2), mT(P(2, 1)), mT(T.N[0]), Pt(1, 2), mT(Pt(2, 1)), mT(L.N[0]))
        r["rev"].append((lab, hc.rel(rev, hc.block(H, 1, 2))))
    rep.worst("J_U (differences of (4)) = omega(c_i M_j^T + c_j M_i) + eps N0", r["JU"], tolfd)
    rep.worst("J_U(1,2) = P12 + P21^T + N0 and J_U(2,1) = P21 + P12^T + N0", r["JU12"], tolfd)
    rep.worst("J_U(2,1) - J_U(1,2)^T = N0 - N0^T = -[e^0]_x / l0^2 (J_U not symmetric)", r["asym"], tolfd)
    rep.worst("J_L = upper formula on (x3,x2,x1) = right column of (6)", r["JL"], tolfd)
    rep.worst("J_U + J_L = Hess theta (SymPy)", r["sum"], tol)
    rep.worst("N0 + N~0 symmetric (l0^2 |S - S^T|)", r["Nsym"], tol)
    rep.worst("N~0 - N~0^T = +[e^0]_x / l0^2", r["Nt"], tol)
    rep.worst("two half-hinges, N0 transposed as claimed: sum = Hess theta", r["one"], tol)
    if offs:
        rep.large("other choices are wrong: min |sum - Hess theta|_F l0^2 / 2", min(o[1] for o in offs), mpf("0.99"))
        rep.worst("... and off by exactly -+[e^0]_x/l0^2 in blocks (1,2),(2,1)", [(o[0], o[2]) for o in offs], tol)
    rep.worst("e0 reversed: H_12 = P12 + P21^T + N0^T + P~12 + P~21^T + N~0^T", r["rev"], tol)
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
