#!/usr/bin/python3
"""Renders a state of a scene (an OBJ written by hinge simulate) to a PNG, with the scene's sphere if it has
one: the pictures of docs/simulator.md.

Usage: render.py SCENE.json STATE.obj OUT.png [--title TEXT]
"""
import argparse
import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_obj(path):
    v, f = [], []
    with open(path) as src:
        for line in src:
            t = line.split()
            if t and t[0] == "v":
                v.append([float(x) for x in t[1:4]])
            elif t and t[0] == "f":
                f.append([int(x.split("/")[0]) - 1 for x in t[1:4]])
    return np.array(v), np.array(f)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scene"), p.add_argument("state"), p.add_argument("out")
    p.add_argument("--title", default=None)
    a = p.parse_args()
    scene = json.load(open(a.scene))
    v, f = read_obj(a.state)
    fig = plt.figure(figsize=(6, 5), dpi=110)
    ax = fig.add_subplot(projection="3d")
    ax.plot_trisurf(v[:, 0], v[:, 1], v[:, 2], triangles=f, color="#6fa8dc", edgecolor="#1c4587",
                    linewidth=0.15, alpha=0.95, shade=True)
    sphere = scene.get("effects", {}).get("sphere")
    if sphere:
        c, r = np.array(sphere["center"]), sphere["radius"]
        uu, vv = np.meshgrid(np.linspace(0, 2 * np.pi, 40), np.linspace(0, np.pi, 20))
        ax.plot_surface(c[0] + r * np.cos(uu) * np.sin(vv), c[1] + r * np.sin(uu) * np.sin(vv),
                        c[2] + r * np.cos(vv), color="#e69138", alpha=0.35, linewidth=0)
    lo, hi = v.min(axis=0), v.max(axis=0)
    mid, half = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(mid[0] - half, mid[0] + half), ax.set_ylim(mid[1] - half, mid[1] + half)
    ax.set_zlim(mid[2] - half, mid[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=25, azim=-60)
    ax.set_xlabel("x (m)"), ax.set_ylabel("y (m)"), ax.set_zlabel("z (m)")
    ax.set_title(a.title or scene.get("name", ""))
    fig.tight_layout()
    fig.savefig(a.out)


if __name__ == "__main__":
    main()
