#!/usr/bin/python3
"""The cantilever against two references, at several resolutions, on regular and irregular strips:
the numbers of docs/scenes.md ("cantilever").

A strip L x W (1 m x 0.1 m; the material of scenes/cantilever.json), its first two columns of vertices
pinned, bends under its weight (static; gravity, StVK stretching, shells bending). For each mesh the
tip deflection (the mean z of the vertices at x = L) of `hinge simulate` is compared with
  - an independent solution of the same discrete model, small deflections: the energy
    sum_e k a_e theta_e^2 with theta_e linearized as the jump of the slope of the piecewise-linear
    deflection across edge e (proofs/plate-limit.md, item 1), a_e = 3 |e|^2 / A_bar, lumped masses as the
    contract says; a sparse linear solve (SciPy). It shares no code with hinge;
  - Kirchhoff's clamped plate strip, w = q L'^4 / (8 D), q = density * thickness * g, L' = L - (the pinned
    length) the free length.
Each mesh runs twice: k from eq. (11) (the default, D/2) and k = D/6 (proofs/plate-limit.md).

Regular strips: the grid, one diagonal per cell. Irregular: the same vertex count, vertices moved by up
to 0.2 of a cell in x and y (fixed seed; the pinned columns and the tip column stay straight; 0.2 keeps
every triangle the right way up, at least a fifth of its nominal area), each cell's
diagonal drawn at random.

Usage: cantilever_study.py HINGE [--cells N ...] [--out ROWS.json] [--plot OUT.png]
  --cells N...: cells along the length (across: N/10); default 20 40 80 160
  --plot: tip / Kirchhoff against the vertex count, with the limits of proofs/plate-limit.md (matplotlib)
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile

import numpy as np
import scipy.sparse as sps
import scipy.sparse.linalg as spl

from objmesh import interior_edges, read_obj

L, W = 1.0, 0.1
MATERIAL = {"density": 1000, "young": 1e10, "poisson": 0.0, "thickness": 0.01}
G = 9.81


def flexural_rigidity():
    m = MATERIAL
    return m["young"] * m["thickness"] ** 3 / (12 * (1 - m["poisson"] ** 2))


def strip(nx, irregular, seed=17):
    """(P, F, pins, tip): nx cells along, nx/10 across; P (n x 2), F counter-clockwise triangles."""
    ny = max(nx // 10, 1)
    rng = random.Random(seed)
    hx, hy = L / nx, W / ny
    idx = lambda i, j: j * (nx + 1) + i  # noqa: E731
    P = np.zeros(((nx + 1) * (ny + 1), 2))
    for j in range(ny + 1):
        for i in range(nx + 1):
            x, y = i * hx, j * hy - W / 2
            if irregular and 2 <= i < nx:
                x += rng.uniform(-0.2, 0.2) * hx
                if 0 < j < ny:
                    y += rng.uniform(-0.2, 0.2) * hy
            P[idx(i, j)] = (x, y)
    F = []
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
            if irregular and rng.random() < 0.5:
                F += [(a, b, d), (b, c, d)]
            else:
                F += [(a, b, c), (a, c, d)]
    pins = [idx(i, j) for j in range(ny + 1) for i in (0, 1)]
    tip = [idx(nx, j) for j in range(ny + 1)]
    return P, np.array(F), pins, tip, hx


def independent_tip(P, F, pins, tip, k):
    """Small-deflection solution of the discrete model: K w = f on the free vertices."""
    m = MATERIAL
    n = len(P)
    area = np.zeros(len(F))
    grads = []  # per triangle: gradient of each barycentric function (3 x 2)
    for t, (i0, i1, i2) in enumerate(F):
        M = np.array([P[i1] - P[i0], P[i2] - P[i0]])
        area[t] = 0.5 * np.linalg.det(M)
        c12 = np.linalg.solve(M, np.eye(2))  # columns: grad of phi_1, phi_2
        grads.append(np.array([-c12[:, 0] - c12[:, 1], c12[:, 0], c12[:, 1]]))
    mass = np.zeros(n)
    for t, f in enumerate(F):
        mass[list(f)] += m["density"] * m["thickness"] * area[t] / 3
    rows, cols, vals = [], [], []
    for (i, j), (t1, t2) in interior_edges(F).items():
        e = P[j] - P[i]
        mvec = np.array([-e[1], e[0]]) / np.linalg.norm(e)
        coef = {}
        for t, sign in ((t1, 1.0), (t2, -1.0)):   # theta' = (grad w_T1 - grad w_T2) . m
            for v, gv in zip(F[t], grads[t]):
                coef[v] = coef.get(v, 0.0) + sign * gv @ mvec
        a_e = 3 * (e @ e) / (area[t1] + area[t2])
        vs, g = list(coef), np.array(list(coef.values()))
        block = 2 * k * a_e * np.outer(g, g)       # Hessian of k a_e theta^2
        for r, vr in enumerate(vs):
            for c, vc in enumerate(vs):
                rows.append(vr), cols.append(vc), vals.append(block[r, c])
    K = sps.csr_matrix((vals, (rows, cols)), shape=(n, n))
    free = np.setdiff1d(np.arange(n), pins)
    w = np.zeros(n)
    w[free] = spl.spsolve(K[free][:, free].tocsc(), -G * mass[free])
    return w[tip].mean()


def simulate(hinge, P, F, pins, tip, k, work):
    obj = os.path.join(work, "strip.obj")
    with open(obj, "w") as out:
        out.writelines("v %.17g %.17g 0\n" % (x, y) for x, y in P)
        out.writelines("f %d %d %d\n" % tuple(i + 1 for i in f) for f in F)
    bending = {"energy": "shells"}
    if k is not None:
        bending["k"] = k
    scene = {"scene": 1, "name": "cantilever-study", "mesh": {"obj": obj}, "material": MATERIAL,
             "solve": {"mode": "static", "newton_tolerance": 1e-10, "residual_tolerance": 1e-5, "max_newton": 200},
             "effects": {"gravity": {"g": [0, 0, -G]}, "stretching": {"model": "stvk"},
                         "bending": bending, "pins": {"vertices": pins}}}
    path = os.path.join(work, "scene.json")
    json.dump(scene, open(path, "w"))
    out = os.path.join(work, "out")
    p = subprocess.run([hinge, "simulate", path, "--out", out, "--quiet", "--overwrite"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("hinge simulate failed: " + p.stderr)
    z = read_obj(os.path.join(out, "final.obj"))[0][:, 2]
    summary = json.load(open(os.path.join(out, "summary.json")))
    return float(np.mean([z[i] for i in tip])), summary


def study(hinge, cells, work):
    D = flexural_rigidity()
    q = MATERIAL["density"] * MATERIAL["thickness"] * G
    rows = []
    for irregular in (False, True):
        for nx in cells:
            P, F, pins, tip, hx = strip(nx, irregular)
            kirchhoff = -q * (L - hx) ** 4 / (8 * D)
            row = {"mesh": "irregular" if irregular else "regular", "cells": "%d x %d" % (nx, max(nx // 10, 1)),
                   "vertices": len(P), "kirchhoff": kirchhoff}
            for label, k in (("eq11", None), ("d6", D / 6)):
                k_value = D / 2 if k is None else k
                tip_sim, summary = simulate(hinge, P, F, pins, tip, k, work)
                tip_ind = independent_tip(P, F, pins, tip, k_value)
                row[label] = {"sim": tip_sim, "independent": tip_ind, "newton": summary["newton_iterations"],
                              "time_s": summary["time_s"]["total"]}
                print("cantilever_study: %s %s k=%s: tip %.6g m (independent %.6g, Kirchhoff %.6g)"
                      % (row["mesh"], row["cells"], label, tip_sim, tip_ind, kirchhoff), file=sys.stderr)
            rows.append(row)
    return rows


def markdown(rows):
    lines = ["| mesh | cells | vertices | tip, k = D/2 (eq. 11) | independent | tip / Kirchhoff "
             "| tip, k = D/6 | tip / Kirchhoff |",
             "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        a, b = r["eq11"], r["d6"]
        lines.append("| %s | %s | %d | %.4f mm | %+.2e | %.4f | %.4f mm | %.4f |" % (
            r["mesh"], r["cells"], r["vertices"], -1e3 * a["sim"], a["sim"] / a["independent"] - 1,
            a["sim"] / r["kirchhoff"], -1e3 * b["sim"], b["sim"] / r["kirchhoff"]))
    return "\n".join(lines)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), dpi=110)
    for ax, label, title, lines in (
            (axes[0], "eq11", "k = D/2 (eq. (11), the default)", [(5 / 12, "5/12: square grid, free to twist"),
                                                                 (1 / 3, "1/3: held straight across")]),
            (axes[1], "d6", "k = D/6 (proofs/plate-limit.md)", [(5 / 4, "5/4: square grid, free to twist"),
                                                               (1.0, "1: Kirchhoff")])):
        for mesh, marker in (("regular", "o-"), ("irregular", "s--")):
            rs = [r for r in rows if r["mesh"] == mesh]
            ax.plot([r["vertices"] for r in rs], [r[label]["sim"] / r["kirchhoff"] for r in rs], marker, label=mesh)
        for y, text in lines:
            ax.axhline(y, color="grey", lw=0.8, ls=":")
            ax.annotate(text, (rows[0]["vertices"], y), textcoords="offset points", xytext=(0, 3), fontsize=8,
                        color="grey")
        ax.set_xscale("log"), ax.set_xlabel("vertices"), ax.set_ylabel("tip deflection / Kirchhoff's")
        ax.set_title(title, fontsize=10), ax.legend(fontsize=8)
    fig.suptitle("Cantilever strip 1 m x 0.1 m under its weight: hinge simulate against q L'^4 / (8 D)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("hinge")
    p.add_argument("--cells", type=int, nargs="+", default=[20, 40, 80, 160])
    p.add_argument("--out", default=None, help="write the rows as JSON here")
    p.add_argument("--plot", default=None, help="draw the convergence into this PNG")
    a = p.parse_args()
    with tempfile.TemporaryDirectory(prefix="cantilever-study-") as work:
        rows = study(a.hinge, a.cells, work)
    if a.out:
        json.dump(rows, open(a.out, "w"), indent=1)
    if a.plot:
        plot(rows, a.plot)
    print(markdown(rows))
    print("\nKirchhoff: q L'^4 / (8 D), L' = L - one cell (the pinned length); 'independent': the relative"
          " difference to the small-deflection solution of the same discrete model")


if __name__ == "__main__":
    main()
