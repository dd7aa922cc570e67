#!/usr/bin/env python3
"""Error against condition number on the hard families (docs/hard-cases.md): one panel per method, one
series per scalar type (and the faithful mode, "double-faithful"), each point one output group of one hinge (normwise error in units of 2^-53,
rounded to double, against the certified oracle), with the bounds the tests hold each to.

Input: the JSON Lines that `HINGE_HARD_REPORT=FILE build/release/tests/methods/methods_hard` appends
({"method", "scalar", "family", "group", "kappa", "error"}). Usage: plot_hard_cases.py REPORT OUT_PREFIX
(writes OUT_PREFIX.svg and OUT_PREFIX.png). Needs matplotlib (python3-matplotlib).
"""
import collections
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHODS = ["fast", "reference", "autodiff", "symbolic"]
SCALARS = ["float", "double", "long-double", "dd", "qd", "float128", "bin128", "mpfr:128", "double-faithful"]
FLOOR = 1e-3  # errors of exactly 0 are drawn here


def main(report, prefix):
    points = collections.defaultdict(list)
    with open(report) as f:
        for line in f:
            r = json.loads(line)
            points[(r["method"], r["scalar"])].append((r["kappa"], max(r["error"], FLOOR)))
    figure, axes = plt.subplots(2, 2, figsize=(13, 10), sharex=True, sharey=True)
    colours = plt.get_cmap("tab10")
    for ax, method in zip(axes.flat, METHODS):
        for i, scalar in enumerate(SCALARS):
            p = points.get((method, scalar))
            if not p:
                continue
            ax.scatter([k for k, _ in p], [e for _, e in p], s=4, alpha=0.35, color=colours(i), label=scalar,
                       rasterized=True)  # 1e5 points: raster inside the SVG
        kappa = [1e-1, 1e36]
        ax.plot(kappa, [0.5 + 16 + 4 * k for k in kappa], "k--", lw=1, label="16 + 4 kappa (double's policy)")
        if method == "fast":
            ax.axhline(4, color="k", lw=1, label="4 units (fast, double)")
            ax.axhline(2, color="grey", lw=1, label="2 units (fast, wider types)")
            ax.axhline(1, color="grey", lw=1, ls=":", label="1 unit (fast, double, the faithful mode)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(method)
        ax.set_ylim(FLOOR / 2, 1e40)
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(fontsize=7, markerscale=3, loc="upper left")
    for ax in axes[1]:
        ax.set_xlabel("condition number kappa_f = L ||J_f|| / ||f||")
    for ax in axes[:, 0]:
        ax.set_ylabel("normwise error, units of 2^-53 (0 drawn at 1e-3)")
    figure.suptitle("Hard families: error against condition number, each output group of each hinge")
    figure.tight_layout()
    for ext in ("svg", "png"):
        figure.savefig(f"{prefix}.{ext}", dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
