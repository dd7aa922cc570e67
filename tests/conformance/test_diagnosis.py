#!/usr/bin/env python3
"""hinge conform's diagnosis through the file route (docs/conformance.md, "Diagnosis"): the text, the JSON
and the HTML report say the same things as hinge.conform in Python (tests/python/test_conform.py grades
every mismatch; here the command's three reports carry them).

Usage: test_diagnosis.py HINGE WORKDIR.
"""
import json
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from script_tests import run_all  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from certified_outputs import certified_outputs  # noqa: E402

HINGE, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)


def certified():
    return certified_outputs(HINGE, WORK)


def conform(lines, name):
    """hinge conform --candidate with --json and --report; (status, text, JSON, HTML)."""
    path = os.path.join(WORK, name + ".jsonl")
    with open(path, "w") as f:
        f.writelines(json.dumps(line) + "\n" for line in lines)
    js, html = os.path.join(WORK, name + ".json"), os.path.join(WORK, name + ".html")
    p = subprocess.run([HINGE, "conform", "--candidate", path, "--json", js, "--report", html], capture_output=True,
                       text=True, timeout=300)
    return p.returncode, p.stdout, json.load(open(js)), open(html).read()


def test_a_negated_angle_is_named_alike_in_the_text_json_and_html_reports():
    lines = [{"id": r["id"], "theta": -r["theta"], "grad": [-g for g in r["grad"]], "hess": [-h for h in r["hess"]]}
             for r in certified()]
    status, text, report, html = conform(lines, "negated")
    assert status == 1 and report["tier"] == "fail"
    assert len(report["diagnosis"]) == 1 and "theta negated (the same as the stencil (x0, x2, x1, x3))" in report["diagnosis"][0]
    assert report["diagnosis"][0] in text
    assert "theta negated" in html
    assert [f["key"] for f in report["findings"]] == ["theta-negated"]
    assert report["findings"][0]["categories"] == [c["category"] for c in report["categories"]]


def test_degrees_are_named():
    c = 180 / math.pi
    lines = [{"id": r["id"], "theta": c * r["theta"], "grad": [c * g for g in r["grad"]],
              "hess": [c * h for h in r["hess"]]} for r in certified()]
    status, text, report, _ = conform(lines, "degrees")
    assert status == 1 and re.search(r"theta in degrees\. Change: return radians", text)


def test_an_inaccurate_candidate_is_approximate_with_no_diagnosis_and_exit_status_1():
    f = 1 + 1e-9
    lines = [{"id": r["id"], "theta": f * r["theta"], "grad": [f * g for g in r["grad"]],
              "hess": [f * h for h in r["hess"]]} for r in certified()]
    status, text, report, _ = conform(lines, "inaccurate")
    assert status == 1 and report["diagnosis"] == [] and "\ndiagnosis (" not in text
    well = next(c for c in report["categories"] if c["category"] == "well-shaped")
    assert well["tier"] == "approximate" and not well["pass"]


def test_the_worst_case_detail_gives_the_inputs_and_the_entry_furthest_off():
    lines = [{"id": r["id"], "theta": r["theta"], "grad": [-g for g in r["grad"]], "hess": r["hess"]}
             for r in certified()]
    _, _, report, _ = conform(lines, "force")
    detail = report["categories"][0]["worst_case_detail"]
    expected = next(r for r in certified() if r["id"] == detail["id"])
    assert detail["output"] == "grad" and detail["got"] == -detail["expected"]
    assert detail["expected"] == expected["grad"][detail["entry"]] and detail["x"] == detail["x_candidate"]


if __name__ == "__main__":
    sys.exit(run_all(globals()))
