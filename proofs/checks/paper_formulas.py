"""The paper's formulas (Tamstorf & Grinspun 2013), transcribed literally in mpmath,
with switches for the printed (erroneous) and corrected variants.  These are the
CLAIMS under test; the checks compare them with theta_oracle.py.

Labels (docs/contract.md, and proofs/sign-convention.md):
  upper T = (x0, x1, x2), counter-clockwise about n;
  lower, in the paper's tilde labels (x~0, x~1, x~2) = (x3, x1, x2), clockwise about nt.
  e_i = x_{i+2} - x_{i+1} (mod 3), l_i = |e_i|, h_i = 2A / l_i,
  cos alpha_i = -e^_{i+1} . e^_{i+2} (interior angle at x_i),
  m_i = OUTWARD unit in-plane normal of edge i,
  M_i = n m_i^T, N_i = M_i / l_i^2, omega_ij = 1 / (h_i h_j).
Block (i, j) of a Hessian = d^2 theta / dx_i dx_j, rows = components of x_i.
"""
from mpmath import mpf

from hinge_common import (vsub, vscale, vadd, dot, cross, norm, unit, outer, mT, madd, mscale,
                          zeros, pt, from_blocks)


class Tri:
    """Quantities of one triangle with labels (p0, p1, p2).

    normal_sign = +1: the labels run counter-clockwise about the normal used (upper T);
    normal_sign = -1: they run clockwise about it (the paper's lower triangle in tilde labels).
    m_outward = False gives inward edge normals (to show that the sign matters)."""

    def __init__(self, p0, p1, p2, normal_sign=1, m_outward=True):
        p = [p0, p1, p2]
        self.p = p
        self.e = [vsub(p[(i + 2) % 3], p[(i + 1) % 3]) for i in range(3)]
        self.l = [norm(e) for e in self.e]
        self.eh = [vscale(1 / l, e) for e, l in zip(self.e, self.l)]
        Nlab = cross(vsub(p1, p0), vsub(p2, p0))          # normal of the label order
        self.A = norm(Nlab) / 2
        nu = unit(Nlab)
        self.n = vscale(normal_sign, nu)
        self.h = [2 * self.A / l for l in self.l]
        self.cos = [-dot(self.eh[(i + 1) % 3], self.eh[(i + 2) % 3]) for i in range(3)]
        sgn = 1 if m_outward else -1
        self.m = [vscale(sgn, cross(eh, nu)) for eh in self.eh]   # e^_i x nu: outward
        self.M = [outer(self.n, m) for m in self.m]
        self.N = [mscale(1 / (l * l), M) for M, l in zip(self.M, self.l)]

    def omega(self, i, j):
        return 1 / (self.h[i] * self.h[j])


def upper(x, **kw):
    return Tri(pt(x, 0), pt(x, 1), pt(x, 2), 1, **kw)


def lower(x, **kw):
    """The lower triangle in the paper's tilde labels (x3, x1, x2), clockwise about nt."""
    return Tri(pt(x, 3), pt(x, 1), pt(x, 2), -1, **kw)


# ------------------------------------------------------------------ eq. (4)
def gradient_eq4(x, swap_alpha=False, lower_normal_sign=1):
    """Eq. (4) as printed, as a 12-vector.  swap_alpha exchanges cos alpha_1 and cos alpha_2
    (a falsification); lower_normal_sign = -1 uses the normal of the tilde label order
    instead of nt (another falsification)."""
    T, L = upper(x), lower(x)
    nt = vscale(lower_normal_sign, L.n)
    c2, c1 = (T.cos[1], T.cos[2]) if swap_alpha else (T.cos[2], T.cos[1])
    t2, t1 = (L.cos[1], L.cos[2]) if swap_alpha else (L.cos[2], L.cos[1])
    g0 = vscale(-1 / T.h[0], T.n)
    g3 = vscale(-1 / L.h[0], nt)
    g1 = vadd(vscale(c2 / T.h[1], T.n), vscale(t2 / L.h[1], nt))
    g2 = vadd(vscale(c1 / T.h[2], T.n), vscale(t1 / L.h[2], nt))
    return g0 + g1 + g2 + g3


def gradient_upper_part(x):
    """The upper-triangle part of eq. (4): (-n/h0, cos a2/h1 n, cos a1/h2 n), 9-vector."""
    T = upper(x)
    return (vscale(-1 / T.h[0], T.n) + vscale(T.cos[2] / T.h[1], T.n) + vscale(T.cos[1] / T.h[2], T.n))


def gradient_lower_part(x):
    """The lower part of eq. (4) at (x1, x2, x3): 9-vector."""
    L = lower(x)
    return (vscale(L.cos[2] / L.h[1], L.n) + vscale(L.cos[1] / L.h[2], L.n) + vscale(-1 / L.h[0], L.n))


# ------------------------------------------------------------------ eq. (5)
def c_coef(T):
    """c_i with the upper-triangle gradient (4) = (c_i / h_i) n: c = (-1, cos a2, cos a1)."""
    return [mpf(-1), T.cos[2], T.cos[1]]


def P(T, i, j, printed=False):
    """P_ij = omega_ij cos(alpha_k) M_j^T with k = the OTHER hinge vertex (k = 3 - i, corrected);
    printed=True uses cos(alpha_i) as printed in eq. (5)."""
    k = i if printed else 3 - i
    return mscale(T.omega(i, j) * T.cos[k], mT(T.M[j]))


def Q(T, j, omega_from=None):
    """Q_j = omega_0j M_j; omega_from lets the tilde Q take omega from the wrong triangle
    (eq. (5) prints Q~_j = omega_0j M~_j)."""
    W = T if omega_from is None else omega_from
    return mscale(W.omega(0, j), T.M[j])


def S(A):
    return madd(A, mT(A))


# ------------------------------------------------------------------ eq. (6)
def hessian_eq6(x, P_printed=False, Qt_printed=False, transpose_rows=False, m_outward=True,
                N0_sign=1):
    """The 12x12 Hessian assembled from eq. (6) and symmetry H_ji = H_ij^T.
    Switches: P_printed (cos alpha_i in P), Qt_printed (omega instead of omega~ in Q~),
    transpose_rows (read every block with rows = components of x_j instead of x_i),
    m_outward=False (inward edge normals in the tilde triangle), N0_sign (flip N0, N~0)."""
    T = upper(x)
    L = lower(x, m_outward=m_outward)
    def Pu(i, j): return P(T, i, j, P_printed)
    def Pl(i, j): return P(L, i, j, P_printed)
    def Ql(j): return Q(L, j, omega_from=T if Qt_printed else None)
    N0 = mscale(N0_sign, T.N[0]); Nt0 = mscale(N0_sign, L.N[0])
    B = {}
    B[(0, 0)] = mscale(-1, S(Q(T, 0)))
    B[(3, 3)] = mscale(-1, S(Ql(0)))
    B[(1, 1)] = madd(S(Pu(1, 1)), mscale(-1, N0), S(Pl(1, 1)), mscale(-1, Nt0))
    B[(2, 2)] = madd(S(Pu(2, 2)), mscale(-1, N0), S(Pl(2, 2)), mscale(-1, Nt0))
    B[(1, 0)] = madd(Pu(1, 0), mscale(-1, Q(T, 1)))
    B[(2, 0)] = madd(Pu(2, 0), mscale(-1, Q(T, 2)))
    B[(1, 3)] = madd(Pl(1, 0), mscale(-1, Ql(1)))
    B[(2, 3)] = madd(Pl(2, 0), mscale(-1, Ql(2)))
    B[(1, 2)] = madd(Pu(1, 2), mT(Pu(2, 1)), N0, Pl(1, 2), mT(Pl(2, 1)), Nt0)
    B[(0, 3)] = zeros(3)
    if transpose_rows:
        B = {k: mT(v) for k, v in B.items()}
    full = dict(B)
    for (i, j), A in B.items():
        if i != j:
            full[(j, i)] = mT(A)
    return from_blocks(full)


# ------------------------------------------------------------------ half-hinge / unified form
EPS = [[0, 0, 0], [0, -1, 1], [0, 1, -1]]


def J_unified(T, i, j, transpose_N0=False):
    """Block (i, j) of the Jacobian of the upper part of eq. (4), derived in hessian.md:
       omega_ij (c_i M_j^T + c_j M_i) + eps_ij N0."""
    c = c_coef(T)
    N0 = mT(T.N[0]) if transpose_N0 else T.N[0]
    return madd(mscale(T.omega(i, j) * c[i], mT(T.M[j])), mscale(T.omega(i, j) * c[j], T.M[i]),
                mscale(EPS[i][j], N0))


def half_hinge_blocks(T, transpose_N0=False):
    """One half-hinge computed from the left column of (6) only, in the triangle's own
    counter-clockwise labels: blocks (0,0), (1,1), (2,2), (1,0), (2,0), (1,2), the rest
    completed by symmetry; transpose_N0 transposes the N0 of block (1,2) (the only block
    the orientation of e0 affects).  Returns {(i, j): 3x3} in local labels."""
    B = {}
    for (i, j) in ((0, 0), (1, 1), (2, 2), (1, 0), (2, 0), (1, 2)):
        B[(i, j)] = J_unified(T, i, j, transpose_N0 and (i, j) == (1, 2))
    for (i, j) in ((1, 0), (2, 0), (1, 2)):
        B[(j, i)] = mT(B[(i, j)])
    return B


# ------------------------------------------------------------------ eq. (7)
def triangle_hessian_eq7(T, c, dagger, printed_d=False):
    """Local 9x9 H^Delta of eq. (7) for a triangle in counter-clockwise labels.
    c[i] = sigma_i psi'_i for edge i; dagger[i] = True transposes R_i."""
    cos = T.cos
    d = [c[(i - 1) % 3] * cos[(i + 1) % 3] + c[(i + 1) % 3] * cos[(i - 1) % 3] - c[i] for i in range(3)]
    R = [mscale(c[i], T.N[i]) for i in range(3)]
    Rd = [mT(R[i]) if dagger[i] else R[i] for i in range(3)]
    B = {}
    for i in range(3):
        for j in (i, (i + 1) % 3):
            base = madd(mscale(T.omega(i, j) * d[i], mT(T.M[j])), mscale(T.omega(i, j) * d[j], T.M[i]))
            if i == j:
                extra = madd(mscale(-1, R[(i + 1) % 3]), mscale(-1, R[(i + 2) % 3]))
            else:
                extra = Rd[(i + 2) % 3]
            B[(i, j)] = madd(base, extra)
            if i != j:
                B[(j, i)] = mT(B[(i, j)])
    return B


def left_column_blocks(T, P_printed=False):
    """The left column of eq. (6) for one triangle in its own counter-clockwise labels, written
    with the building blocks of eq. (5) (P printed or corrected): blocks (0,0), (1,1), (2,2),
    (1,0), (2,0), (1,2), completed by symmetry."""
    def Pp(i, j): return P(T, i, j, P_printed)
    B = {(0, 0): mscale(-1, S(Q(T, 0))),
         (1, 1): madd(S(Pp(1, 1)), mscale(-1, T.N[0])),
         (2, 2): madd(S(Pp(2, 2)), mscale(-1, T.N[0])),
         (1, 0): madd(Pp(1, 0), mscale(-1, Q(T, 1))),
         (2, 0): madd(Pp(2, 0), mscale(-1, Q(T, 2))),
         (1, 2): madd(Pp(1, 2), mT(Pp(2, 1)), T.N[0])}
    for (i, j) in ((1, 0), (2, 0), (1, 2)):
        B[(j, i)] = mT(B[(i, j)])
    return B
