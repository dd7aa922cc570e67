#!/usr/bin/env python3
"""hinge conform's tiers and its JSON report (docs/conformance.md, "Tiers").

Usage: test_tiers.py HINGE WORKDIR. (The peers' failure modes graded "fail": ctest conform_plugin_peer_*.)
"""
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from script_tests import run_all  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from certified_outputs import certified_outputs  # noqa: E402

HINGE, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)
TIERS = ["correctly-rounded", "faithful", "4u", "policy", "approximate", "fail"]


def conform(*args):
    """Runs hinge conform ... --json FILE; returns (exit status, text report, JSON report)."""
    path = os.path.join(WORK, "report.json")
    if os.path.exists(path):
        os.remove(path)
    p = subprocess.run([HINGE, "conform", *args, "--json", path], capture_output=True, text=True, timeout=300)
    report = json.load(open(path)) if os.path.exists(path) else None
    return p.returncode, p.stdout, report


def oracle_file():
    return certified_outputs(HINGE, WORK)


def write(lines, name):
    path = os.path.join(WORK, name)
    with open(path, "w") as f:
        for line in lines:
            f.write(json.dumps(line) + "\n")
    return path


def tiers(report):
    return {c["category"]: c["tier"] for c in report["categories"]}


def test_the_oracles_outputs_are_correctly_rounded_in_every_category():
    status, text, report = conform("--candidate", write(oracle_file(), "same.jsonl"))
    assert status == 0 and report["pass"]
    assert set(tiers(report).values()) == {"correctly-rounded"}, tiers(report)
    assert all(c["tier"] == "correctly-rounded" for c in report["cases"]) and len(report["cases"]) == 306
    assert "correctly-rounded" in text


def test_one_ulp_off_is_graded_by_exactly_what_it_costs():
    lines = oracle_file()
    target = next(line for line in lines if line["id"].startswith("well-shaped/") and line["theta"] != 0)
    moved = math.nextafter(target["theta"], math.inf)
    target["theta"] = moved
    status, _, report = conform("--candidate", write(lines, "one-ulp.jsonl"))
    certified = next(line for line in oracle_file() if line["id"] == target["id"])["theta"]
    # The normwise error of theta: |one ulp| / |theta| in units of 2^-53, between 1 and 2 by the binade.
    units = abs(moved - certified) / abs(certified) / 2.0**-53
    expected = "faithful" if units <= 1 else "4u"
    assert status == 0 and tiers(report)["well-shaped"] == expected, (units, tiers(report))
    case = next(c for c in report["cases"] if c["id"] == target["id"])
    assert case["tier"] == expected and case["error"]["theta"] == units
    assert {t for k, t in tiers(report).items() if k != "well-shaped"} == {"correctly-rounded"}


def test_the_fast_kernel_reaches_4u_in_every_category():
    status, _, report = conform("--method", "fast")
    assert status == 0 and report["pass"]
    assert all(TIERS.index(t) <= TIERS.index("4u") for t in tiers(report).values()), tiers(report)


def test_the_reference_is_graded_down_where_its_theta_loses_digits_but_passes():
    status, _, report = conform("--method", "reference", "--category", "near-flat", "--category", "well-shaped")
    assert status == 0 and tiers(report)["near-flat"] == "policy", tiers(report)  # eq. (4)-(6) literal: see numerics.md


def test_json_report_has_the_per_category_and_per_case_fields():
    _, _, report = conform("--method", "fast", "--category", "needles")
    assert report["policy"] == {"base": 16, "c": 4}
    (category,) = report["categories"]
    assert set(category) >= {"category", "cases", "missing", "nonfinite", "failed", "median", "worst", "worst_case",
                             "worst_ratio", "pass", "tier"}
    assert set(category["worst"]) == {"theta", "grad", "hess"}
    assert all(set(c) >= {"id", "category", "status", "error", "tolerance", "kappa", "pass", "tier"} for c in report["cases"])


def test_json_without_a_candidate_is_a_usage_error():
    p = subprocess.run([HINGE, "conform", "--inputs", "--json", os.path.join(WORK, "x.json")], capture_output=True)
    assert p.returncode == 2 and b"--json and --report go with" in p.stderr


if __name__ == "__main__":
    sys.exit(run_all(globals()))
