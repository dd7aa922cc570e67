#!/usr/bin/python3
"""Renders states of a scene (OBJ files written by hinge simulate) to a PNG, with the scene's sphere if it has
one: the pictures of docs/scenes.md. Several states go side by side, one panel each, or into one panel
with --spread (each shifted by DY metres in y: the five beams).

Usage: render.py SCENE.json STATE.obj [STATE.obj ...] OUT.png [--titles T ...] [--spread DY] [--exaggerate F]
  --exaggerate F: z multiplied by F (small deflections; the title should say so)
"""
import argparse
import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from objmesh import read_obj  # noqa: E402


def draw(ax, scene, meshes, title, zscale=1.0):
    for v, f in meshes:
        ax.plot_trisurf(v[:, 0], v[:, 1], v[:, 2], triangles=f, color="#6fa8dc", edgecolor="#1c4587",
                        linewidth=0.15, alpha=0.95, shade=True)
    pts = np.vstack([v for v, _ in meshes])
    sphere = scene.get("effects", {}).get("sphere")
    if sphere:
        c, r = np.array(sphere["center"]), sphere["radius"]
        uu, vv = np.meshgrid(np.linspace(0, 2 * np.pi, 40), np.linspace(0, np.pi, 20))
        ax.plot_surface(c[0] + r * np.cos(uu) * np.sin(vv), c[1] + r * np.sin(uu) * np.sin(vv),
                        c[2] + r * np.cos(vv), color="#e69138", alpha=0.35, linewidth=0)
        pts = np.vstack([pts, c - r, c + r])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    mid, half = (lo + hi) / 2, (hi - lo).max() / 2
    ax.set_xlim(mid[0] - half, mid[0] + half), ax.set_ylim(mid[1] - half, mid[1] + half)
    ax.set_zlim(mid[2] - half, mid[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=25, azim=-60)
    ax.set_xlabel("x (m)"), ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)" if zscale == 1 else "z (m) x %g" % zscale)
    ax.set_title(title, fontsize=10)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("scene")
    p.add_argument("files", nargs="+", help="STATE.obj ... OUT.png")
    p.add_argument("--titles", nargs="*", default=None)
    p.add_argument("--spread", type=float, default=None)
    p.add_argument("--exaggerate", type=float, default=1.0)
    a = p.parse_args()
    if len(a.files) < 2:
        p.error("give at least one STATE.obj and the OUT.png")
    states, out = a.files[:-1], a.files[-1]
    scene = json.load(open(a.scene))
    meshes = [read_obj(s) for s in states]
    for v, _ in meshes:
        v[:, 2] *= a.exaggerate
    titles = a.titles or [scene.get("name", "")] * len(states)
    if a.spread is not None:
        for i, (v, _) in enumerate(meshes):
            v[:, 1] += i * a.spread
        fig = plt.figure(figsize=(6, 5), dpi=110)
        draw(fig.add_subplot(projection="3d"), scene, meshes, titles[0], a.exaggerate)
    else:
        fig = plt.figure(figsize=(5 * len(meshes), 4.6), dpi=110)
        for i, (m, t) in enumerate(zip(meshes, titles)):
            draw(fig.add_subplot(1, len(meshes), i + 1, projection="3d"), scene, [m], t, a.exaggerate)
    fig.tight_layout()
    fig.savefig(out)


if __name__ == "__main__":
    main()
