#!/usr/bin/python3
"""Renders the plots of `hinge study` from its study.json (docs/study.md):

  pareto.svg/.png     time per hinge against error, one point per method x scalar type, the frontier drawn
  histogram.svg/.png  the distribution of Hessian errors per hinge (the paper's Fig. 6)
  scaling.svg/.png    time per mesh evaluation against vertices in double, with the fitted k (Fig. 7,
                      Table 2), and per interior edge in every scalar type

Usage: plot_study.py STUDY.json OUTDIR. Needs matplotlib (Debian: python3-matplotlib). The SVG files are
deterministic (fixed hash salt, no date), so committed plots change only when the numbers do.
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "hinge-study"
matplotlib.rcParams["font.size"] = 9
import matplotlib.pyplot as plt  # noqa: E402

FLOOR = 0.05  # errors of exactly 0 units are drawn here on the logarithmic axes
METHODS = ["reference", "fast", "autodiff", "symbolic"]
MARKERS = {"reference": "s", "fast": "o", "autodiff": "^", "symbolic": "D"}


def scalar_order(name):
    order = ["float", "double", "long-double", "dd", "float128", "bin128", "qd"]
    if name in order:
        return (order.index(name), 0)
    if name.startswith("mpfr:"):
        return (len(order), int(name.split(":")[1]))
    return (len(order) + 1, 0)


def colours(names):
    """One distinct colour per scalar type, in the types' order (tab10 holds the ten of the full study)."""
    names = sorted(set(names), key=scalar_order)
    cmap = plt.get_cmap("tab10" if len(names) <= 10 else "tab20")
    return {n: cmap(i) for i, n in enumerate(names)}


def save(fig, outdir, name):
    fig.savefig(os.path.join(outdir, name + ".svg"), metadata={"Date": None})
    fig.savefig(os.path.join(outdir, name + ".png"), dpi=130, metadata={"Software": None})
    plt.close(fig)


def frontier(points):
    """The points (t, e) no other point beats in both; sorted by time."""
    best = []
    for t, e, *rest in sorted(points):
        if not best or e < best[-1][1]:
            best.append((t, e, *rest))
    return best


def pareto(study, outdir):
    rows = [r for r in study["rows"] if "hess" in r["ns_per_hinge"] and r["error_u"]]
    colour = colours(r["scalar"] for r in rows)
    typical = "well-shaped" if "well-shaped" in study["inputs"]["categories"] else study["inputs"]["categories"][0]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    panels = [
        ("worst of any output (theta, gradient, Hessian), all categories",
         lambda r: max(g["max"] for e in r["error_u"].values() for g in e.values())),
        (f"median Hessian error over {typical}", lambda r: r["error_u"][typical]["hess"]["median"] if typical in r["error_u"] else None),
    ]
    for ax, (title, error) in zip(axes, panels):
        points = []
        for r in rows:
            e = error(r)
            if e is None:
                continue
            failed = r["failed"] + r["nonfinite"]
            t = r["ns_per_hinge"]["hess"]
            ax.scatter(t, max(e, FLOOR), marker=MARKERS.get(r["method"], "x"), color=colour[r["scalar"]],
                       edgecolors="black" if failed else "none", linewidths=1.2, s=36, zorder=3)
            if not failed:
                points.append((t, max(e, FLOOR), r["method"], r["scalar"]))
        best = frontier(points)
        if best:
            xs, ys = [], []
            for t, e, *_ in best:
                if xs:
                    xs.append(t)
                    ys.append(ys[-1])
                xs.append(t)
                ys.append(e)
            ax.plot(xs, ys, color="0.3", lw=1, zorder=2, label="frontier")
            for t, e, m, s in best:
                ax.annotate(f"{m}/{s}", (t, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("ns per hinge: theta, gradient and Hessian (one thread)")
        ax.set_ylabel(f"normwise error, units of 2^-53 (0 drawn at {FLOOR})")
        ax.set_title(title)
        ax.grid(True, which="major", lw=0.3)
    handles = [plt.Line2D([], [], marker=MARKERS[m], ls="", color="0.4", label=m) for m in METHODS]
    handles += [plt.Line2D([], [], marker="o", ls="", color=c, label=s) for s, c in colour.items()]
    handles.append(plt.Line2D([], [], marker="o", ls="", mfc="none", mec="black", label="failed or non-finite on some hinge"))
    fig.legend(handles=handles, loc="lower center", ncol=8, fontsize=7, frameon=False)
    fig.suptitle(f"What accuracy costs: {study['machine']['cpu']}, {study['machine']['clock_ghz']:.2f} GHz, "
                 f"{study['inputs']['hinges']} hinges ({study['inputs']['source']})")
    fig.tight_layout(rect=(0, 0.08, 1, 0.95))
    save(fig, outdir, "pareto")


def histogram(study, outdir):
    rows = study["rows"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    lo, hi = math.log10(FLOOR), 16
    bins = [lo + i * (hi - lo) / 60 for i in range(61)]

    def draw(ax, selection, key, title, colour_of):
        for r in selection:
            errs = [math.log10(max(e, FLOOR)) for e in r["hess_errors_u"]]
            if not errs:
                continue
            ax.hist(errs, bins=bins, histtype="step", lw=1.3, label=key(r), color=colour_of(r))
        ax.set_xlabel("log10 of the Hessian's normwise error, units of 2^-53 (per hinge)")
        ax.set_ylabel("hinges (log scale: the tails are the hard cases)")
        ax.set_yscale("log")
        ax.set_title(title)
        ax.legend(fontsize=7)

    method_colour = {m: plt.get_cmap("tab10")(i) for i, m in enumerate(METHODS)}
    draw(axes[0], [r for r in rows if r["scalar"] == "double"], lambda r: r["method"], "every method in double",
         lambda r: method_colour.get(r["method"], "k"))
    fast = [r for r in rows if r["method"] == "fast"]
    colour = colours(r["scalar"] for r in fast)
    draw(axes[1], sorted(fast, key=lambda r: scalar_order(r["scalar"])), lambda r: r["scalar"],
         "fast in every scalar type, rounded to double", lambda r: colour[r["scalar"]])
    fig.suptitle("Distribution of Hessian errors against the certified oracle (the paper's Fig. 6)")
    fig.tight_layout()
    save(fig, outdir, "histogram")


def scaling(study, outdir):
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.8))
    method_colour = {m: plt.get_cmap("tab10")(i) for i, m in enumerate(METHODS)}
    # Left: every method in double against size (the paper's Fig. 7), fitted t = a n^k.
    for m in study["mesh"]:
        if m["scalar"] != "double" or not m["vertices"]:
            continue
        c = method_colour.get(m["method"], "k")
        ax.plot(m["vertices"], m["seconds"], marker=MARKERS.get(m["method"], "x"), ls="", color=c, ms=4)
        label = m["method"] + (f": k = {m['k']:.3f}" if "k" in m else "")
        if "k" in m:
            xs = [m["vertices"][0], m["vertices"][-1]]
            ax.plot(xs, [math.exp(m["ln_a"]) * x ** m["k"] for x in xs], color=c, lw=1, label=label)
        else:
            ax.plot([], [], color=c, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("vertices")
    ax.set_ylabel("seconds per evaluation (one thread)")
    ax.set_title("double: time against size, t = a n^k (Fig. 7)")
    ax.grid(True, which="major", lw=0.3)
    ax.legend(fontsize=7)
    # Right: ns per interior edge (the median over the sizes measured) in every scalar type.
    scalars = sorted({m["scalar"] for m in study["mesh"]}, key=scalar_order)
    for method in METHODS:
        xs, ys = [], []
        for m in study["mesh"]:
            if m["method"] == method and m["ns_per_edge"]:
                v = sorted(m["ns_per_edge"])
                xs.append(scalars.index(m["scalar"]))
                ys.append(v[len(v) // 2])
        if xs:
            order = sorted(range(len(xs)), key=lambda k: xs[k])
            bx.plot([xs[k] for k in order], [ys[k] for k in order], marker=MARKERS[method], color=method_colour[method],
                    lw=1, label=method)
    bx.set_xticks(range(len(scalars)))
    bx.set_xticklabels(scalars, rotation=30, ha="right")
    bx.set_yscale("log")
    bx.set_ylabel("ns per interior edge (median over sizes)")
    bx.set_title("every scalar type: energy, gradient and Hessian per edge")
    bx.grid(True, which="major", lw=0.3)
    bx.legend(fontsize=7)
    fig.suptitle("Mesh evaluation (tan energy, the benchmark's cloth)")
    fig.tight_layout()
    save(fig, outdir, "scaling")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_study.py STUDY.json OUTDIR")
    with open(sys.argv[1]) as f:
        study = json.load(f)
    pareto(study, sys.argv[2])
    histogram(study, sys.argv[2])
    scaling(study, sys.argv[2])


if __name__ == "__main__":
    main()
