#!/usr/bin/env python3
"""`hinge study` against docs/contract.md: what it writes, that its errors are the true ones (an independent
comparison of `hinge eval` with `hinge oracle`), and its bad-input handling.

Usage: test_study.py HINGE_BINARY. Each check is a function test_*; script_tests.run_all runs them all, prints one line
per check and "N passed, M failed", and exits nonzero if any failed.
"""
import json
import math
import os
import subprocess
import sys
import tempfile

from script_tests import run_all

HINGE = sys.argv[1]


def run(args, stdin=""):
    p = subprocess.run([HINGE] + args, input=stdin, capture_output=True, text=True, timeout=600)
    return p.returncode, p.stdout, p.stderr


def lines(text):
    return [json.loads(l) for l in text.splitlines() if l.strip()]


def normwise(candidate, certified):
    """||candidate - certified|| / ||certified|| in units of 2^-53 (docs/study.md), for nonzero certified."""
    d = math.hypot(*(a - b for a, b in zip(candidate, certified)))  # hypot: no overflow at extreme scales
    n = math.hypot(*certified)
    return d / n / 2.0 ** -53


def test_quick_study_writes_every_output_with_four_methods_and_eight_scalar_types():
    with tempfile.TemporaryDirectory() as d:
        # The quick study's rows and sizes, with short budgets: what it writes, not how long it measures.
        code, out, err = run(["study", "--quick", "--out", d, "--budget", "0.2"])
        assert code == 0, err
        for name in ["study.json", "study.md", "pareto.svg", "pareto.png", "histogram.svg", "histogram.png",
                     "scaling.svg", "scaling.png"]:
            assert os.path.getsize(os.path.join(d, name)) > 0, name
        s = json.load(open(os.path.join(d, "study.json")))
        assert s["version"] == 2 and s["inputs"]["source"] == "built-in"
        assert len({r["method"] for r in s["rows"]}) >= 4
        assert len({r["scalar"] for r in s["rows"]}) >= 8
        for category in ["well-shaped", "near-flat", "near-folded", "needles", "short-hinge-edges", "offsets", "scales"]:
            assert category in s["inputs"]["categories"], category
        for r in s["rows"]:
            assert set(r["ns_per_hinge"]) == {"theta", "grad", "hess"}, r["method"] + r["scalar"]
            assert all(v > 0 for v in r["ns_per_hinge"].values())
            for groups in r["error_u"].values():
                assert set(groups) == {"theta", "grad", "hess"}
                assert all(set(g) >= {"median", "max"} and g["median"] <= g["max"] for g in groups.values())
        assert {m["method"] for m in s["mesh"]} == {"reference", "fast", "autodiff", "symbolic"}
        assert all(len(m["vertices"]) == len(m["ns_per_edge"]) >= 1 for m in s["mesh"])
        assert set(s["build"]) >= {"version", "commit", "compiler", "flags"}
        assert "fast" in out and "double" in out  # the summary table
        # The plots are drawn by the script beside the program, deterministically: drawn again from the same
        # study.json, every SVG has the same bytes (committed plots change only when the numbers do).
        again = os.path.join(d, "again")
        os.mkdir(again)
        script = os.path.join(os.path.dirname(HINGE), "plot_study.py")
        subprocess.run([sys.executable, script, os.path.join(d, "study.json"), again], check=True, timeout=300)
        for name in ["pareto.svg", "histogram.svg", "scaling.svg"]:
            assert open(os.path.join(d, name), "rb").read() == open(os.path.join(again, name), "rb").read(), name


def test_errors_agree_with_an_independent_comparison_against_the_oracle():
    with tempfile.TemporaryDirectory() as d:
        inputs = os.path.join(d, "hinges.jsonl")
        code, out, _ = run(["conform", "--inputs"])
        assert code == 0
        with open(inputs, "w") as f:
            f.write(out)
        hinges = lines(out)
        code, _, err = run(["study", "--input", inputs, "--methods", "fast,reference", "--scalars", "double",
                            "--no-mesh", "--no-plots", "--out", d])
        assert code == 0, err
        s = json.load(open(os.path.join(d, "study.json")))
        assert s["inputs"]["hinges"] == len(hinges)
        certified = {r["id"]: r for r in lines(run(["oracle", "--input", inputs])[1])}
        for method in ["fast", "reference"]:
            computed = {r["id"]: r for r in lines(run(["eval", "--method", method, "--input", inputs])[1])}
            worst = {}
            for h in hinges:
                c, e = computed[h["id"]], certified[h["id"]]
                for group in ["grad", "hess"]:
                    v = normwise(c[group], e[group])
                    worst[(h["category"], group)] = max(worst.get((h["category"], group), 0), v)
                if e["theta"] != 0:
                    v = abs(c["theta"] - e["theta"]) / abs(e["theta"]) / 2.0 ** -53
                    worst[(h["category"], "theta")] = max(worst.get((h["category"], "theta"), 0), v)
            row = next(r for r in s["rows"] if r["method"] == method and r["scalar"] == "double")
            assert row["hinges_measured"] == len(hinges) and row["failed"] == row["nonfinite"] == 0
            for (category, group), v in worst.items():
                reported = row["error_u"][category][group]["max"]
                # Both compute the same normwise formula from the same doubles: equal up to the rounding of
                # the sums of squares (a few units of 2^-53 of the ratio itself).
                assert abs(reported - v) <= 1e-12 * max(v, 1) + 1e-12, (method, category, group, reported, v)


def test_category_field_groups_the_users_hinges_and_sample_draws_reproducibly():
    with tempfile.TemporaryDirectory() as d:
        inputs = os.path.join(d, "hinges.jsonl")
        hinges = lines(run(["conform", "--inputs"])[1])
        with open(inputs, "w") as f:
            for i, h in enumerate(hinges):
                record = {"id": h["id"], "x": h["x"]}
                if i % 2:
                    record["category"] = "odd"
                f.write(json.dumps(record) + "\n")
        outs = []
        for k in range(2):
            out_dir = os.path.join(d, str(k))
            code, _, err = run(["study", "--input", inputs, "--sample", "50", "--methods", "fast", "--scalars", "double",
                                "--no-mesh", "--no-plots", "--out", out_dir])
            assert code == 0, err
            outs.append(json.load(open(os.path.join(out_dir, "study.json"))))
        assert outs[0]["inputs"]["hinges"] == 50 and sorted(outs[0]["inputs"]["categories"]) == ["input", "odd"]
        assert outs[0]["rows"][0]["error_u"] == outs[1]["rows"][0]["error_u"]  # the same 50 hinges


def test_bad_input_exits_with_the_documented_status_and_writes_nothing():
    with tempfile.TemporaryDirectory() as d:
        out_dir = os.path.join(d, "out")
        bad = os.path.join(d, "bad.jsonl")
        with open(bad, "w") as f:
            f.write('{"id": "a", "x": [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0]}\n{"id": "b", "x": [1, 2]}\n')
        empty = os.path.join(d, "empty.jsonl")
        open(empty, "w").close()
        cases = [
            (["--input", os.path.join(d, "missing.jsonl")], 1, "missing.jsonl"),
            (["--input", bad], 1, "bad.jsonl:2"),
            (["--input", empty], 1, "no hinge"),
            (["--methods", "fast,frobnicate"], 2, "frobnicate"),
            (["--scalars", "quad"], 2, "quad"),
            (["--sample", "5"], 2, "--input"),
        ]
        for args, status, named in cases:
            code, _, err = run(["study", "--out", out_dir, "--no-mesh", "--no-plots"] + args)
            assert code == status, (args, code, err)
            assert named in err, (args, err)
            assert not os.path.exists(os.path.join(out_dir, "study.json")), args


if __name__ == "__main__":
    sys.exit(run_all(globals()))
