#!/usr/bin/python3
"""Writes the crumpling scene's meshes (deterministic): meshes/crumple-rest.obj, a flat 1 m x 1 m cloth of
31 x 31 vertices (the grid of docs/contract.md, 6.2), and meshes/crumple.obj, the same cloth pleated like an
accordion: six panels of five cells, alternately tilted up and down by 85 degrees, so the five fold lines
start at theta = +-170 degrees (near-folded) and the cloth at 9% of its width. crumple.json releases it
above the sphere: the tan energy's psi' at 170 degrees is about 5200 times its value at 30 degrees.

Usage: crumple.py                 write the meshes
       crumple.py angles OUT_DIR   the largest |theta| of each frame of a run (NumPy)
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
N, SIZE, PANEL, TILT_DEG, HEIGHT = 31, 1.0, 5, 85.0, 0.45


def write(path, pts, comment):
    s = N
    with open(path, "w") as out:
        out.write("# crumple.py: %s\n" % comment)
        out.writelines("v %.17g %.17g %.17g\n" % p for p in pts)
        for j in range(s - 1):
            for i in range(s - 1):
                p, q, r, t = i + s * j, i + 1 + s * j, i + 1 + s * (j + 1), i + s * (j + 1)
                out.write("f %d %d %d\nf %d %d %d\n" % (p + 1, q + 1, r + 1, p + 1, r + 1, t + 1))


def main():
    h = SIZE / (N - 1)
    rest = [(i * h - SIZE / 2, j * h - SIZE / 2, HEIGHT) for j in range(N) for i in range(N)]
    tilt = math.radians(TILT_DEG)
    xs, zs = [0.0], [0.0]
    for i in range(1, N):
        up = ((i - 1) // PANEL) % 2 == 0
        xs.append(xs[-1] + h * math.cos(tilt))
        zs.append(zs[-1] + (h if up else -h) * math.sin(tilt))
    x0 = (xs[0] + xs[-1]) / 2
    pleated = [(xs[i] - x0, j * h - SIZE / 2, HEIGHT + zs[i]) for j in range(N) for i in range(N)]
    os.makedirs(os.path.join(HERE, "meshes"), exist_ok=True)
    write(os.path.join(HERE, "meshes", "crumple-rest.obj"), rest, "the flat rest shape, 31 x 31")
    write(os.path.join(HERE, "meshes", "crumple.obj"), pleated,
          "the initial state: pleated, fold lines at theta = +-%g degrees" % (2 * TILT_DEG))
    print("crumple.py: wrote meshes/crumple.obj and meshes/crumple-rest.obj")


def largest_angle(path):
    """max |theta| over the interior edges of an OBJ (theta = atan2(|n x nt| sign, n . nt), degrees)."""
    import numpy as np
    from objmesh import interior_edges, read_obj
    v, f = read_obj(path)
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    pairs = np.array(list(interior_edges(f).values()))
    a, b = n[pairs[:, 0]], n[pairs[:, 1]]
    angle = np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), (a * b).sum(axis=1))
    return math.degrees(angle.max())


def angles(out):
    frames = sorted(os.listdir(os.path.join(out, "frames")))
    for name in frames:
        print("%s: largest |theta| %.1f degrees" % (name, largest_angle(os.path.join(out, "frames", name))))


if __name__ == "__main__":
    angles(sys.argv[2]) if len(sys.argv) == 3 and sys.argv[1] == "angles" else main()
