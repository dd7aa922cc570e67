#!/usr/bin/env python3
"""Check for proofs/block-counts.md: the number of 3x3 block updates ("calls to the
assembly function", section 4.2) of the three assembly schemes, by enumeration on meshes.

  separate loops (triangles, then hinges): 6F + 10E   (E = interior edges = hinges)
  combined loop (each hinge's outer product assigned to one of its faces, the blocks among
  that face's three vertices merged into the face's own 6 updates):       6F + 4E
  naive per-hinge Hessian:                                              10E
The merged assembly is verified to produce the same matrix (random integer contributions).
Counting identities: 3F = 2E + E_b (each face has 3 edge slots), hence E <= 3F/2 and
6F + 10E >= 14E, 6F + 4E >= 8E, with equality on closed meshes; Euler V - E_all + F = chi.
Regular (m x m quads, split) grid: V = (m+1)^2, F = 2m^2, E_all = 3m^2 + 2m, E = 3m^2 - 2m,
E_b = 4m; the ratios tend to 14 and 8 (the paper's 13E and 7E assume E = 2F, impossible).
--falsify paper-ratio: assert the paper's approximations 6F+10E ~ 13E and 6F+4E ~ 7E (E = 2F)
--falsify miscount   : assert 6F + 9E and 6F + 3E (the (x0, x3) block of the outer product forgotten)
"""
import itertools
import random

import hinge_common as hc

VARIANTS = {"paper-ratio": "6F+10E ~ 13E and 6F+4E ~ 7E, i.e. E ~ 2F",
            "miscount": "outer product with 9 unique blocks: 6F+9E and 6F+3E"}


def grid(m):
    idx = lambda i, j: i * (m + 1) + j
    F = []
    for i in range(m):
        for j in range(m):
            a, b, c, d = idx(i, j), idx(i, j + 1), idx(i + 1, j + 1), idx(i + 1, j)
            F += [(a, b, c), (a, c, d)]
    return (m + 1) ** 2, F


def torus(m):
    idx = lambda i, j: (i % m) * m + (j % m)
    F = []
    for i in range(m):
        for j in range(m):
            a, b, c, d = idx(i, j), idx(i, j + 1), idx(i + 1, j + 1), idx(i + 1, j)
            F += [(a, b, c), (a, c, d)]
    return m * m, F


def octahedron():
    return 6, [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]


def analyse(V, F, rng):
    directed = {}
    for f in F:
        for i in range(3):
            directed[(f[(i + 1) % 3], f[(i + 2) % 3])] = (f, f[i])
    edges = {tuple(sorted(k)) for k in directed}
    hinges = {}
    for (a, b), (f, apex) in directed.items():
        if (b, a) in directed and a < b:
            hinges[(a, b)] = (f, directed[(b, a)][0], (apex, a, b, directed[(b, a)][1]))
    E_all, E, E_b = len(edges), len(hinges), len(edges) - len(hinges)
    pair = lambda p, q: (min(p, q), max(p, q))
    # contributions: each face has 6 unique local blocks, each hinge 10 unique outer-product blocks
    face_c = {f: {pair(f[i], f[j]): rng.randint(-9, 9) for i in range(3) for j in range(i, 3)} for f in F}
    hinge_c = {h: {pair(p, q): rng.randint(-9, 9) for p, q in itertools.combinations_with_replacement(quad, 2)}
               for h, (_, _, quad) in hinges.items()}
    # separate loops
    sep, calls_sep = {}, 0
    for f in F:
        for k, v in face_c[f].items():
            sep[k] = sep.get(k, 0) + v; calls_sep += 1
    for h in hinges:
        for k, v in hinge_c[h].items():
            sep[k] = sep.get(k, 0) + v; calls_sep += 1
    # combined loop: hinge assigned to the face where its edge runs min -> max (the "CCW" face)
    assigned = {f: [] for f in F}
    for (a, b), (fu, fl, quad) in hinges.items():
        assigned[fu].append((a, b))       # fu contains a -> b with a < b
    comb, calls_comb = {}, 0
    for f in F:
        local = dict(face_c[f])
        for h in assigned[f]:
            for k, v in hinge_c[h].items():
                if k in local:
                    local[k] += v              # merged into the face's own update
                else:
                    comb[k] = comb.get(k, 0) + v; calls_comb += 1
        for k, v in local.items():
            comb[k] = comb.get(k, 0) + v; calls_comb += 1
    naive = 10 * E
    distinct = len(set(sep))
    return dict(V=V, F=len(F), E_all=E_all, E=E, E_b=E_b, sep=calls_sep, comb=calls_comb, naive=naive,
                same=(sep == comb), distinct=distinct)


def main():
    args = hc.parse_args(__doc__, VARIANTS)
    rep = hc.Report("proofs.block-counts", "block updates of the assembly schemes (section 4.2)", args.falsify)
    rng = random.Random(7)
    meshes = [("octahedron (closed)", octahedron(), 2)]
    meshes += [("grid m=%d" % m, grid(m), 1) for m in (1, 2, 5, 20, 100)]
    meshes += [("torus m=%d" % m, torus(m), 0) for m in (3, 10)]
    ks, kc = (9, 3) if args.falsify == "miscount" else (10, 4)
    results = {}
    for name, (V, F), chi in meshes:
        r = analyse(V, F, rng)
        results[name] = r
        print("  %-20s V=%-6d F=%-6d E_all=%-6d hinges E=%-6d E_b=%-4d  separate=%-7d combined=%-7d naive=%-7d"
              " distinct blocks=%d" % (name, r["V"], r["F"], r["E_all"], r["E"], r["E_b"], r["sep"], r["comb"],
                                       r["naive"], r["distinct"]))
        F_, E = r["F"], r["E"]
        rep.true("%s: separate loops = 6F + %dE" % (name, ks), r["sep"] == 6 * F_ + ks * E,
                 "%d vs %d" % (r["sep"], 6 * F_ + ks * E))
        rep.true("%s: combined loop = 6F + %dE, same matrix" % (name, kc), r["comb"] == 6 * F_ + kc * E and r["same"],
                 "%d vs %d" % (r["comb"], 6 * F_ + kc * E))
        rep.true("%s: 3F = 2E + E_b and Euler V - E_all + F = %d" % (name, chi),
                 3 * F_ == 2 * E + r["E_b"] and r["V"] - r["E_all"] + F_ == chi)
        rep.true("%s: 6F + 10E >= 14E and 6F + 4E >= 8E (equality iff closed)" % name,
                 r["sep"] >= 14 * E and r["comb"] >= 8 * E and ((r["sep"] == 14 * E) == (r["E_b"] == 0)))
        if name.startswith("grid"):
            m = int(name.split("=")[1])
            rep.true("%s: closed forms V, F, E_all, E, E_b" % name,
                     (r["V"], F_, r["E_all"], E, r["E_b"]) == ((m + 1) ** 2, 2 * m * m, 3 * m * m + 2 * m,
                                                               3 * m * m - 2 * m, 4 * m))
    big = results["grid m=100"]
    F_, E = big["F"], big["E"]
    if args.falsify == "paper-ratio":
        target_sep, target_comb, target_EF = 13, 7, 2
    else:
        target_sep, target_comb, target_EF = 14, 8, 1.5
    rep.small("large grid: E/F -> %s" % target_EF, abs(E / F_ - target_EF), 0.02)
    rep.small("large grid: (6F + 10E)/E -> %s" % target_sep, abs(big["sep"] / E - target_sep), 0.05)
    rep.small("large grid: (6F + 4E)/E -> %s" % target_comb, abs(big["comb"] / E - target_comb), 0.05)
    rep.small("large grid: naive 10E, combined/naive -> %s" % (target_comb / 10), abs(big["comb"] / big["naive"] - target_comb / 10), 0.01)
    rep.finish()


if __name__ == "__main__":
    hc.run(main)
