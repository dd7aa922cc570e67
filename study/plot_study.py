#!/usr/bin/python3
"""Renders the plots of `hinge study` from its study.json (docs/study.md):

  pareto.svg/.png     time per hinge (as a multiple of fast in double, measured side by side) against error,
                      one point per method x scalar type, the frontier drawn and its points labelled with
                      their time (ns and cycles) and worst error; outside rows drawn apart (stars, named)
  histogram.svg/.png  the distribution of Hessian errors per hinge (the paper's Fig. 6), exact zeros in a
                      bin of their own
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

FLOOR = 1e-6  # errors of exactly 0 units are drawn here on the logarithmic axes (the faithful mode reaches 1e-4)
METHODS = ["reference", "fast", "autodiff", "symbolic", "faithful", "oracle"]
MARKERS = {"reference": "s", "fast": "o", "autodiff": "^", "symbolic": "D", "faithful": "P", "oracle": "h"}
OUTSIDE = "*"  # outside rows: a star, named beside it


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
    """The points (t, e) no other point beats in both (at equal error the faster); sorted by time."""
    best = []
    for t, e, *rest in sorted(points):
        if not best or e < best[-1][1]:
            best.append((t, e, *rest))
    return best


def label(r):
    return r["method"] if r.get("outside") else f"{r['method']}/{r['scalar']}"


def worst(r):
    return max(g["max"] for e in r["error_u"].values() for g in e.values())


def units(v):
    return "0" if v == 0 else f"{v:.2g}" if v < 1e4 else f"{v:.1e}"


def pareto(study, outdir):
    rows = [r for r in study["rows"] if "hess" in r.get("x_fast", {}) and r["error_u"]]
    colour = colours(r["scalar"] for r in rows if not r.get("outside"))
    typical = "well-shaped" if "well-shaped" in study["inputs"]["categories"] else study["inputs"]["categories"][0]
    fast = next((r for r in rows if r["method"] == "fast" and r["scalar"] == "double" and not r.get("outside")), None)
    ghz = study["machine"]["clock_ghz"]
    fig, axes = plt.subplots(1, 2, figsize=(12, 5.2))
    panels = [
        ("worst of any output (theta, gradient, Hessian), all categories", worst, True),
        (f"median Hessian error over {typical}",
         lambda r: r["error_u"][typical]["hess"]["median"] if typical in r["error_u"] else None, False),
    ]
    for ax, (title, error, study_frontier) in zip(axes, panels):
        points = []
        for r in rows:
            e = error(r)
            if e is None:
                continue
            failed = r["failed"] + r["nonfinite"]
            t = r["x_fast"]["hess"]
            if r.get("outside"):
                ax.scatter(t, max(e, FLOOR), marker=OUTSIDE, color="white", edgecolors="black", linewidths=1, s=110,
                           zorder=4)
                ax.annotate(r["method"] + " (outside)", (t, max(e, FLOOR)), textcoords="offset points",
                            xytext=(6, -10), fontsize=7, style="italic")
            else:
                ax.scatter(t, max(e, FLOOR), marker=MARKERS.get(r["method"], "x"), color=colour[r["scalar"]],
                           edgecolors="black" if failed else "none", linewidths=1.2, s=36, zorder=3)
            if not failed:
                points.append((t, max(e, FLOOR), r))
        # the left panel's frontier is the study's own (study.json's on_frontier); the right one's computed here
        best = sorted((p for p in points if p[2]["on_frontier"]), key=lambda p: p[0]) if study_frontier \
            else frontier(points)
        if best:
            xs, ys = [], []
            for t, e, _ in best:
                if xs:
                    xs.append(t)
                    ys.append(ys[-1])
                xs.append(t)
                ys.append(e)
            ax.plot(xs, ys, color="0.3", lw=1, zorder=2, label="frontier")
            for k, (t, e, r) in enumerate(best):
                ns = r["ns_per_hinge"]["hess"]
                text = f"{label(r)}\n{ns:.0f} ns, {ns * ghz:.0f} cycles, {units(error(r))} u"
                ax.annotate(text, (t, e), textcoords="offset points", xytext=(5, 6 if k % 2 == 0 else -22),
                            fontsize=6.5, bbox={"boxstyle": "round,pad=0.2", "fc": "white", "ec": "0.7", "lw": 0.5})
        ax.set_xscale("log")
        ax.set_yscale("log")
        base = f" ({fast['ns_per_hinge']['hess']:.0f} ns)" if fast else ""
        ax.set_xlabel(f"time per hinge, theta, gradient and Hessian, as a multiple of fast in double{base}")
        ax.set_ylabel(f"normwise error, units of 2^-53 (0 drawn at {FLOOR})")
        ax.set_title(title)
        ax.grid(True, which="major", lw=0.3)
    present = [m for m in METHODS if any(r["method"] == m and not r.get("outside") for r in rows)]
    handles = [plt.Line2D([], [], marker=MARKERS[m], ls="", color="0.4", label=m) for m in present]
    handles += [plt.Line2D([], [], marker="o", ls="", color=c, label=s) for s, c in colour.items()]
    if any(r.get("outside") for r in rows):
        handles.append(plt.Line2D([], [], marker=OUTSIDE, ls="", mfc="white", mec="black", ms=9, label="outside"))
    handles.append(plt.Line2D([], [], marker="o", ls="", mfc="none", mec="black", label="failed or non-finite on some hinge"))
    fig.legend(handles=handles, loc="lower center", ncol=9, fontsize=7, frameon=False)
    fig.suptitle(f"What accuracy costs: {study['machine']['cpu']}, {ghz:.2f} GHz, "
                 f"{study['inputs']['hinges']} hinges ({study['inputs']['source']})")
    fig.tight_layout(rect=(0, 0.08, 1, 0.95))
    save(fig, outdir, "pareto")


def histogram(study, outdir):
    rows = study["rows"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    lo, hi = -2, 16
    zero = lo - 1.5  # exact zeros: a bin of their own, left of the axis's first decade
    bins = [zero - 0.5, zero + 0.5] + [lo + i * (hi - lo) / 60 for i in range(61)]

    def draw(ax, selection, key, title, colour_of):
        for r in selection:
            errs = [zero if e == 0 else min(max(math.log10(e), lo), hi) for e in r["hess_errors_u"]]
            if not errs:
                continue
            ax.hist(errs, bins=bins, histtype="step", lw=1.3, label=key(r), color=colour_of(r),
                    ls="--" if r.get("outside") else "-")
        ax.set_xticks([zero] + list(range(lo, hi + 1, 2)))
        ax.set_xticklabels(["exact"] + [str(v) for v in range(lo, hi + 1, 2)])
        ax.set_xlabel("log10 of the Hessian's normwise error, units of 2^-53 (per hinge; exact zeros in a bin of their own)")
        ax.set_ylabel("hinges (log scale: the tails are the hard cases)")
        ax.set_yscale("log")
        ax.set_title(title)
        ax.legend(fontsize=7)

    method_colour = {m: plt.get_cmap("tab10")(i) for i, m in enumerate(METHODS)}
    draw(axes[0], [r for r in rows if r["scalar"] == "double"], label, "every method in double (outside: dashed)",
         lambda r: "0.2" if r.get("outside") else method_colour.get(r["method"], "k"))
    fast = [r for r in rows if r["method"] == "fast" and not r.get("outside")]
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
