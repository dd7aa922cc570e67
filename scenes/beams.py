#!/usr/bin/python3
"""The paper's five beams (section 7.1, Fig. 5): a horizontal beam, one end clamped, bending under gravity,
damped to equilibrium; five materials from soft cloth to stiff shell, each at 366, 787 and 1372 vertices.

  beams.py meshes              writes meshes/beam-{366,787,1372}.obj and beam-{1..5}.json (787 vertices):
                               what scenes/ ships (deterministic: the same bytes every run)
  beams.py table HINGE [--out F.json] [--rows F.json]
                               runs the 5 x 3 scenes with bending by fast, reference and autodiff and prints
                               Table 1's figure (bending's share of the time) and the Newton iterations

The beam: 1 m x 0.1 m, an irregular triangulation (Delaunay, SciPy) of a grid of nx x ny vertices with
extra vertices at the centres of randomly chosen cells, so the three resolutions hit the paper's counts
exactly (51 x 6 + 60, 81 x 9 + 58, 111 x 12 + 40). The clamp: the vertices of the first two columns,
numbered first. The materials: Y = 10 GPa, nu = 0.3, 1000 kg/m^3, thickness 0.5, 1, 2, 4, 8 mm (beam 1 droops
like cloth, beam 5 deflects under 1% of its length); tan bending with eq. (11)'s k, the exact Hessian;
viscous damping by mass drag 5/s (its bending part is fast-only with the exact Hessian, and the table
compares methods); dt = 10 ms, 300 steps (3 s).
"""
import argparse
import json
import os
import random
import subprocess
import sys
import tempfile

import numpy as np
from scipy.spatial import Delaunay

from objmesh import interior_edges, read_obj

HERE = os.path.dirname(os.path.abspath(__file__))
L, W = 1.0, 0.1
RESOLUTIONS = {366: (51, 6), 787: (81, 9), 1372: (111, 12)}
THICKNESS_MM = [0.5, 1, 2, 4, 8]
METHODS = ["fast", "reference", "autodiff"]


def mesh(n_vertices, seed=5):
    """(P, F, clamped): P (n x 3), F counter-clockwise faces, the clamped vertices 0 .. clamped-1."""
    nx, ny = RESOLUTIONS[n_vertices]
    hx, hy = L / (nx - 1), W / (ny - 1)
    pts = [(i * hx, j * hy - W / 2) for i in range(nx) for j in range(ny)]
    cells = [(i, j) for i in range(1, nx - 1) for j in range(ny - 1)]  # not in the clamp's cells
    for i, j in random.Random(seed).sample(cells, n_vertices - nx * ny):
        pts.append(((i + 0.5) * hx, (j + 0.5) * hy - W / 2))
    P = np.array(pts)
    clamp = [v for v in range(len(P)) if P[v, 0] < 1.5 * hx]
    order = clamp + [v for v in range(len(P)) if P[v, 0] >= 1.5 * hx]
    P = P[order]
    tri = Delaunay(P)
    F = []
    for a, b, c in tri.simplices:
        area = np.cross(P[b] - P[a], P[c] - P[a])
        if abs(area) < 1e-12 * hx * hy:
            continue
        F.append((a, b, c) if area > 0 else (a, c, b))
    P3 = np.column_stack([P, np.zeros(len(P))])
    return P3, np.array(F), len(clamp)


def write_obj(path, P, F):
    with open(path, "w") as out:
        out.write("# beams.py: a 1 m x 0.1 m beam, %d vertices, the clamped ones first\n" % len(P))
        out.writelines("v %.17g %.17g %.17g\n" % tuple(p) for p in P)
        out.writelines("f %d %d %d\n" % tuple(int(i) + 1 for i in f) for f in F)


def scene(beam, n_vertices, clamped, mesh_path, method="fast"):
    h = THICKNESS_MM[beam - 1] * 1e-3
    return {"scene": 1, "name": "beam-%d" % beam,
            "mesh": {"obj": mesh_path},
            "material": {"density": 1000, "young": 10 ** 10, "poisson": 0.3, "thickness": h},
            "solve": {"mode": "dynamic", "dt": 0.01, "steps": 300, "newton_tolerance": 1e-6,
                      # the residual's rounding floor: Y h = 5e6 N/m against a vertex's weight of 5e-4 N
                      # leaves max |g_v| at about 1.4e-6 F where Newton's step is 1e-15 L
                      "residual_tolerance": 1e-5, "hessian": "exact"},
            "effects": {"gravity": {"g": [0, 0, -9.81]},
                        "stretching": {"model": "stvk"},
                        "bending": {"energy": "tan", "method": method},
                        "damping": {"model": "viscous", "mass": 5.0},
                        "pins": {"vertices": list(range(clamped))}},
            "output": {"every": 50}}


def write_scene(path, s):
    with open(path, "w") as out:
        def value(k, v):
            if k != "effects":
                return json.dumps(v)
            return "{\n" + ",\n".join("   %s: %s" % (json.dumps(e), json.dumps(p)) for e, p in v.items()) + "\n }"
        out.write("{" + ",\n ".join("%s: %s" % (json.dumps(k), value(k, v)) for k, v in s.items()) + "}\n")


def cmd_meshes():
    os.makedirs(os.path.join(HERE, "meshes"), exist_ok=True)
    for n in RESOLUTIONS:
        P, F, clamped = mesh(n)
        write_obj(os.path.join(HERE, "meshes", "beam-%d.obj" % n), P, F)
        if n == 787:
            for beam in range(1, 6):
                write_scene(os.path.join(HERE, "beam-%d.json" % beam), scene(beam, n, clamped, "meshes/beam-787.obj"))
        print("beams.py: meshes/beam-%d.obj: %d vertices, %d faces, %d clamped" % (n, len(P), len(F), clamped))


def cmd_table(hinge, out_json):
    rows = []
    with tempfile.TemporaryDirectory(prefix="beams-") as work:
        for n in RESOLUTIONS:
            P, F, clamped = mesh(n)
            obj = os.path.join(work, "beam-%d.obj" % n)
            write_obj(obj, P, F)
            for beam in range(1, 6):
                for method in METHODS:
                    path = os.path.join(work, "scene.json")
                    write_scene(path, scene(beam, n, clamped, obj, method))
                    out = os.path.join(work, "out-%d-%d-%s" % (n, beam, method))
                    p = subprocess.run([hinge, "simulate", path, "--out", out, "--quiet", "--overwrite"],
                                       capture_output=True, text=True)
                    if p.returncode != 0:
                        sys.exit("beams.py: hinge simulate failed (exit %d): %s" % (p.returncode, p.stderr))
                    summary = json.load(open(os.path.join(out, "summary.json")))
                    frames = sorted(os.listdir(os.path.join(out, "frames")))
                    before, last = (read_obj(os.path.join(out, "frames", f))[0] for f in frames[-2:])
                    z = last[:, 2].min()
                    still = np.abs(last - before).max()   # motion over the last output interval (0.5 s)
                    row = {"vertices": n, "beam": beam, "method": method, "status": summary["status"],
                           "exit": p.returncode, "newton": summary["newton_iterations"],
                           "total_s": summary["time_s"]["total"], "bending_share": summary["bending_share"],
                           "lowest_z": z, "last_motion": still}
                    rows.append(row)
                    print("beams.py: %d vertices, beam %d, %s: %s, %d Newton iterations, %.2f s, bending %.1f%%,"
                          " lowest point %.4f m" % (n, beam, method, row["status"], row["newton"], row["total_s"],
                                                    100 * row["bending_share"], z), file=sys.stderr)
    if out_json:
        json.dump(rows, open(out_json, "w"), indent=1)
    print_table(rows)


def print_table(rows):
    print("| vertices | beam | Newton its | time (fast) | ms per iteration | bending us per interior edge per "
          "iteration | bending share: fast | reference | autodiff | lowest z | motion in the last 0.5 s |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for n in RESOLUTIONS:
        edges = len(interior_edges(mesh(n)[1]))
        for beam in range(1, 6):
            r = {x["method"]: x for x in rows if x["vertices"] == n and x["beam"] == beam}
            f = r["fast"]
            bending_us = 1e6 * f["bending_share"] * f["total_s"] / f["newton"] / edges
            print("| %d | %d (%g mm) | %d | %.2f s | %.2f | %.2f | %.1f%% | %.1f%% | %.1f%% | %.4f m | %.1e m |" % (
                n, beam, THICKNESS_MM[beam - 1], f["newton"], f["total_s"], 1e3 * f["total_s"] / f["newton"],
                bending_us, 100 * f["bending_share"], 100 * r["reference"]["bending_share"],
                100 * r["autodiff"]["bending_share"], f["lowest_z"], f["last_motion"]))
    for m in METHODS:
        shares = [100 * x["bending_share"] for x in rows if x["method"] == m]
        print("%s: bending share %.1f-%.1f%% over the 15 runs" % (m, min(shares), max(shares)))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    sub.add_parser("meshes")
    t = sub.add_parser("table")
    t.add_argument("hinge")
    t.add_argument("--out", default=None, help="write the runs' figures (JSON) here")
    t.add_argument("--rows", default=None, help="print the table of an earlier --out instead of running")
    a = p.parse_args()
    if a.cmd == "meshes":
        cmd_meshes()
    elif a.rows:
        print_table(json.load(open(a.rows)))
    else:
        cmd_table(a.hinge, a.out)


if __name__ == "__main__":
    main()
