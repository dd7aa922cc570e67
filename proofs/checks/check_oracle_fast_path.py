#!/usr/bin/env python3
"""Check for proofs/oracle-fast-path.md: the rounding-error bounds of the oracle's fast path, in exact
rational arithmetic.

Python's float is IEEE double with rounding to nearest (ties to even), subnormals included, and
float(Fraction) rounds a rational correctly: so every double-double step of oracle/src/bounded.hpp is
replayed exactly here (a fused multiply-add is float(a * b + c) over Fractions), and its claimed bound
is compared with its true error, a rational.  Operands are drawn well scaled, near underflow, and with
cancellation.

1. Addition: hi + lo differs from A + B (A = a.hi + a.lo, ...) by at most u (|t| + |v|), and by at
   most that plus eta = 2^-1000 when |t| + |v| < 2^-960 (where u (|t| + |v|) itself may underflow).
2. Multiplication: hi + lo differs from A B by at most u (|q| + |c| + |v|) + |a.lo b.lo|, plus eta
   unless both operands are doubles whose product is at least 2^-960 (then the product is exact).
3. The bound's own arithmetic: err computed in rounding to nearest, times 1 + 2^-49, is at least the
   exact value of the propagated formula |A| eb + |B| ea + ea eb + rounding, with ma = |a.hi| +
   |a.lo| in place of |A|.
4. Reciprocal and square root: the residual bounds |r - 1/D| <= (|1 - r D~| + |r| eD) / lower(D) and
   |l - sqrt(S)| <= (|l^2 - S~| + eS) / l hold (exact residuals, D and S drawn within their errors).
5. The decision: when (|lo| + err) (1 + 2^-49) < half the gap from hi to its nearer neighbour, both
   ends of [hi + lo - err, hi + lo + err] round to hi.
6. The arctangent's series: for |z| <= 1/128 the sum through z^17 differs from atan z by less than
   |z|^19 / 19 (mpmath at 1200 bits), and atan(a) = atan(c) + atan((a - c) / (1 + a c)) for c = k/64
   nearest to a in [0, 1].
7. The normals: for a + b + c = 0, a x b = b x c = c x a exactly (rationals), so a triangle's normal may
   be taken from any two of its edges in cyclic order; and |a x b| = |a| |b| sin of their angle.
--falsify add-v   : drop u |v| from the addition's bound (the rounding of e + t)
--falsify mul-lolo: drop |a.lo b.lo| from the product's bound (the term the product leaves out)
"""
import math
import random
from fractions import Fraction as Q

from mpmath import mp, mpf

import hinge_common as hc

VARIANTS = {"add-v": "the addition's bound without u |v|",
            "mul-lolo": "the product's bound without |a.lo b.lo|"}

U = Q(1, 2 ** 53)
ETA = Q(1, 2 ** 1000)
TINY = 2.0 ** -960
INFLATE = 1 + 2.0 ** -49


def rn(x):
    return float(x)


def fma(a, b, c):
    return float(Q(a) * Q(b) + Q(c))


def two_sum(a, b):
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


def add(a, b, falsify):
    """bounded.hpp operator+: returns (hi, lo, rounding bound) for exact operands a, b = (hi, lo)."""
    s, e = two_sum(a[0], b[0])
    t = a[1] + b[1]
    v = e + t
    hi, lo = two_sum(s, v)
    m = abs(t) + (0.0 if falsify == "add-v" else abs(v))
    bound = U * Q(m) + (ETA if 0 < m < TINY else 0)
    return hi, lo, bound


def mul(a, b, falsify):
    p = a[0] * b[0]
    pe = fma(a[0], b[0], -p)
    q = a[1] * b[0]
    c = fma(a[0], b[1], q)
    v = pe + c
    hi, lo = two_sum(p, v)
    ma, mb = abs(a[0]) + abs(a[1]), abs(b[0]) + abs(b[1])
    exact = a[1] == 0 and b[1] == 0 and ma * mb >= TINY
    lolo = 0 if falsify == "mul-lolo" else abs(Q(a[1]) * Q(b[1]))
    bound = 0 if exact or ma == 0 or mb == 0 else U * (Q(abs(q)) + Q(abs(c)) + Q(abs(v))) + lolo + ETA
    return hi, lo, bound


def dd(rng, lo_e, hi_e):
    """A normalized double-double (hi = RN(hi + lo)) of magnitude 2^[lo_e, hi_e], sometimes a double."""
    h = math.ldexp(rng.uniform(1, 2), rng.randint(lo_e, hi_e)) * rng.choice((-1, 1))
    if rng.random() < 0.2:
        return h, 0.0
    l = math.ldexp(rng.uniform(-0.5, 0.5), math.frexp(h)[1] - 53)
    s = h + l
    return s, (h - s) + l


def value(x):
    return Q(x[0]) + Q(x[1])


def check_bounds(rep, rng, falsify, ranges):
    worst = {"add": Q(0), "mul": Q(0)}
    ok = {"add": True, "mul": True}
    for lo_e, hi_e in ranges:
        for i in range(3000):
            a = dd(rng, lo_e, hi_e)
            b = dd(rng, lo_e, hi_e)
            if i % 3 == 0:  # cancellation: b near -a
                b = (-a[0], rng.choice((0.0, -a[1], math.ldexp(a[0], -70))))
                s = b[0] + b[1]
                b = (s, (b[0] - s) + b[1])
            for name, op, exact in (("add", add, value(a) + value(b)), ("mul", mul, value(a) * value(b))):
                hi, lo, bound = op(a, b, falsify)
                error = abs(Q(hi) + Q(lo) - exact)
                if error > bound:
                    ok[name] = False
                if bound > 0:
                    worst[name] = max(worst[name], error / bound)
    rep.true("1. addition: |hi + lo - (A + B)| <= u (|t| + |v|) (+ eta below 2^-960), 18000 draws",
             ok["add"], "largest error / bound %.3g" % float(worst["add"]))
    rep.true("2. product: |hi + lo - A B| <= u (|q| + |c| + |v|) + |a.lo b.lo| (+ eta), 18000 draws",
             ok["mul"], "largest error / bound %.3g" % float(worst["mul"]))


def check_err_arithmetic(rep, rng):
    ok = True
    for _ in range(5000):
        a, b = dd(rng, -40, 40), dd(rng, -40, 40)
        ea = math.ldexp(abs(a[0]), -rng.randint(60, 110))
        eb = math.ldexp(abs(b[0]), -rng.randint(60, 110))
        q, c = a[1] * b[0], fma(a[0], b[1], a[1] * b[0])
        v = fma(a[0], b[0], -(a[0] * b[0])) + c
        ma, mb = abs(a[0]) + abs(a[1]), abs(b[0]) + abs(b[1])
        rounding = 2.0 ** -53 * (abs(q) + abs(c) + abs(v)) + abs(a[1] * b[1])
        computed = (ma * eb + mb * ea + ea * eb + rounding) * INFLATE
        exact = (abs(value(a)) * Q(eb) + abs(value(b)) * Q(ea) + Q(ea) * Q(eb)
                 + U * (Q(abs(q)) + Q(abs(c)) + Q(abs(v))) + abs(Q(a[1]) * Q(b[1])))
        ok &= Q(computed) >= exact
    rep.true("3. err computed in rounding to nearest, times 1 + 2^-49, bounds the exact propagated error (5000)", ok)


def check_residual_bounds(rep, rng):
    ok = True
    for _ in range(3000):
        d = dd(rng, -30, 30)
        ed = math.ldexp(abs(d[0]), -rng.randint(60, 100))
        true_d = value(d) + Q(ed) * Q(rng.uniform(-1, 1))
        r0 = 1 / d[0]
        r = Q(r0) + Q(r0) * (1 - Q(r0) * value(d))
        low = abs(value(d)) - Q(ed)
        bound = (abs(1 - r * value(d)) + abs(r) * Q(ed)) / low
        ok &= abs(r - 1 / true_d) <= bound
        s = (abs(d[0]), abs(d[1]) if d[0] > 0 else -abs(d[1]))
        s = (s[0] + s[1], 0.0)
        es = math.ldexp(s[0], -rng.randint(60, 100))
        true_s = Q(s[0]) + Q(es) * Q(rng.uniform(-1, 1))
        l = Q(math.sqrt(s[0]))
        mp.prec = 400
        sqrt_true = mp.sqrt(mpf(true_s.numerator) / true_s.denominator)
        bound = (abs(l * l - Q(s[0])) + Q(es)) / l
        ok &= abs(mpf(l.numerator) / l.denominator - sqrt_true) <= mpf(bound.numerator) / bound.denominator
    rep.true("4. reciprocal and square root: the residual bounds hold (3000 each)", ok)


def check_decision(rep, rng):
    ok, decided = True, 0
    for _ in range(20000):
        hi, lo = dd(rng, -1000, 1000)
        if rng.random() < 0.1:
            hi, lo = math.ldexp(1.0, rng.randint(-900, 900)), 0.0  # powers of two: the gap below is half
        err = math.ldexp(abs(hi), -rng.randint(50, 60))
        up, down = math.nextafter(abs(hi), math.inf) - abs(hi), abs(hi) - math.nextafter(abs(hi), 0)
        if (abs(lo) + err) * INFLATE >= min(up, down) / 2:
            continue
        decided += 1
        centre = Q(hi) + Q(lo)
        ok &= float(centre - Q(err)) == hi and float(centre + Q(err)) == hi
    rep.true("5. a decided interval rounds to hi at both ends", ok and decided > 1000, "%d decided" % decided)


def check_arctangent(rep, rng):
    mp.prec = 1200  # |z|^19 / 19 reaches 2^-400 of z for the smallest z drawn
    ok = True
    for _ in range(2000):
        z = mpf(rng.uniform(-1, 1)) / 128
        series = sum((-1) ** j * z ** (2 * j + 1) / (2 * j + 1) for j in range(9))
        ok &= abs(mp.atan(z) - series) < abs(z) ** 19 / 19
        a = mpf(rng.uniform(0, 1))
        c = mpf(round(float(a) * 64)) / 64
        ok &= abs(mp.atan(a) - mp.atan(c) - mp.atan((a - c) / (1 + a * c))) < mpf(2) ** -1100
        ok &= abs((a - c) / (1 + a * c)) <= mpf(1) / 128
    rep.true("6. atan series through z^17 within |z|^19 / 19 for |z| <= 1/128; the table's addition formula", ok)


def check_cyclic_normals(rep, rng):
    def cross(u, v):
        return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    ok = True
    for _ in range(2000):
        a = tuple(Q(rng.uniform(-1, 1)) for _ in range(3))
        b = tuple(Q(rng.uniform(-1, 1)) for _ in range(3))
        c = tuple(-x - y for x, y in zip(a, b))
        ok &= cross(a, b) == cross(b, c) == cross(c, a)
    rep.true("7. a + b + c = 0 gives a x b = b x c = c x a exactly (2000 rational triples)", ok)


def main():
    args = hc.parse_args(__doc__, VARIANTS)
    rep = hc.Report("proofs.oracle-fast-path", "the fast path's rounding-error bounds, in exact rationals",
                    args.falsify)
    rng = random.Random(20261204)
    check_bounds(rep, rng, args.falsify, [(-30, 30), (-1074, -1000), (-1060, -940)])
    check_err_arithmetic(rep, rng)
    check_residual_bounds(rep, rng)
    check_decision(rep, rng)
    check_arctangent(rep, rng)
    check_cyclic_normals(rep, rng)
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
