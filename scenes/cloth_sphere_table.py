#!/usr/bin/python3
"""The paper's Table 1 on the cloth-sphere, and what each Hessian treatment costs: the numbers of
docs/scenes.md ("The paper's Table 1").

scenes/cloth-sphere.json run with its grid's "vertices" set to n x n, its bending "method" and the
scene's "hessian" set per row, one run each, one thread, side by side in one session; the figures from
each run's summary.json (Newton iterations, the worst step's, the rungs, time, bending's share).

Usage: cloth_sphere_table.py HINGE [--rows N:METHOD:HESSIAN ...] [--out ROWS.json]
  default rows: 11 and 21 with fast, reference and autodiff under the exact Hessian, fast under projected
  and gauss-newton; 41 with fast under all three.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT = [f"{n}:{m}:exact" for n in (11, 21) for m in ("fast", "reference", "autodiff")]
DEFAULT += [f"{n}:fast:{h}" for n in (11, 21) for h in ("projected", "gauss-newton")]
DEFAULT += ["41:fast:exact", "41:fast:projected", "41:fast:gauss-newton"]


def run(hinge, n, method, hessian, work):
    scene = json.load(open(os.path.join(HERE, "cloth-sphere.json")))
    scene["mesh"]["grid"]["vertices"] = [n, n]
    scene["effects"]["bending"]["method"] = method
    scene["solve"]["hessian"] = hessian
    name = f"{n}-{method}-{hessian}"
    path = os.path.join(work, name + ".json")
    json.dump(scene, open(path, "w"))
    out = os.path.join(work, name)
    subprocess.run([hinge, "simulate", path, "--out", out, "--quiet"], check=False, stdout=subprocess.DEVNULL)
    s = json.load(open(os.path.join(out, "summary.json")))
    return {"n": n, "method": method, "hessian": hessian, "status": s["status"],
            "reason": s.get("reason", ""), "iterations": s["newton_iterations"],
            "worst_step": s["solver"]["newton_per_step"]["max"], "rungs": s["solver"]["rungs"],
            "factorizations": s["solver"]["factorizations"], "total": s["time_s"]["total"],
            "linear": s["time_s"]["linear_solve"], "bending": s["time_s"]["effects"].get("bending", 0.0),
            "share": s["bending_share"]}


def table(rows):
    print("| n x n | bending | Hessian | Newton iterations | worst step | rungs newton / projected | total (s) "
          "| ms per iteration | linear solve share | bending ms per iteration | bending share |")
    print("|---|---|---|---:|---:|---|---:|---:|---:|---:|---:|")
    for r in rows:
        it = max(r["iterations"], 1)
        status = "" if r["status"] == "ok" else f" (failed: {r['reason']})"
        print(f"| {r['n']} | {r['method']} | {r['hessian']}{status} | {r['iterations']} | {r['worst_step']} "
              f"| {r['rungs']['newton']} / {r['rungs']['projected']} | {r['total']:.2f} "
              f"| {1000 * r['total'] / it:.2f} | {100 * r['linear'] / r['total']:.0f}% "
              f"| {1000 * r['bending'] / it:.2f} | {100 * r['share']:.1f}% |")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("hinge")
    p.add_argument("--rows", nargs="+", default=DEFAULT)
    p.add_argument("--out")
    a = p.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for spec in a.rows:
            n, method, hessian = spec.split(":")
            rows.append(run(a.hinge, int(n), method, hessian, work))
            print(f"{spec}: {rows[-1]['iterations']} iterations, {rows[-1]['total']:.1f} s", file=sys.stderr)
    if a.out:
        json.dump(rows, open(a.out, "w"), indent=1)
    table(rows)


if __name__ == "__main__":
    main()
