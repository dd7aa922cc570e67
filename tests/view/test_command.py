#!/usr/bin/env python3
"""hinge view as a user meets it (docs/contract.md 6.3): a page from a dynamic run (one frame per frame file,
final.obj added where it adds a state), from a static run (one frame), from a failed run (its frames and its
status); a folder that is not a simulation's output and frames that do not fit: exit 1 naming the folder or
the frame, no page left behind; usage errors: exit 2; nothing in the page points elsewhere, and three.js's
MIT notice is in it.

Usage: test_command.py HINGE_BINARY
"""
import json
import os
import re
import atexit
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tools"))
from script_tests import run_all  # noqa: E402

HINGE = sys.argv[1]
THREE = Path("/usr/share/javascript/three")  # Debian's libjs-three, embedded in the page as it is


def scene(**overrides):
    s = {"scene": 1, "name": "t",
         "mesh": {"grid": {"vertices": [6, 5], "size": [0.5, 0.4], "center": [0, 0, 0.3], "plane": "xy"}},
         "material": {"density": 400, "young": 2e6, "poisson": 0.3, "thickness": 0.0005},
         "solve": {"mode": "dynamic", "dt": 0.01, "steps": 10},
         "effects": {"gravity": {"g": [0, 0, -9.81]}, "stretching": {"model": "stvk"}, "bending": {"energy": "tan"},
                     "sphere": {"center": [0, 0, 0], "radius": 0.25}},
         "output": {"every": 4}}
    s.update(overrides)
    return s


def temporary_folder():
    d = Path(tempfile.mkdtemp(prefix="hinge-view-"))
    atexit.register(shutil.rmtree, d, ignore_errors=True)
    return d


def simulate(s):
    d = temporary_folder()
    (d / "scene.json").write_text(json.dumps(s))
    subprocess.run([HINGE, "simulate", str(d / "scene.json"), "--out", str(d / "out"), "--quiet"], capture_output=True)
    return d / "out"


def view(*args):
    return subprocess.run([HINGE, "view", *map(str, args)], capture_output=True, text=True)


def data(page):
    html = Path(page).read_text()
    return json.loads(re.search(r'<script type="application/json" id="hinge-run">(.*?)</script>', html, re.S).group(1))


def check_self_contained(html):
    """Nothing in the page loads from elsewhere: three.js and its controls removed (Debian's files, unchanged;
    their own namespace strings and licence comments are theirs), the rest names no resource at all."""
    assert "default-src 'none'" in html, "the page's Content-Security-Policy is missing"
    assert "Copyright © 2010-2017 three.js authors" in html and "Permission is hereby granted" in html, \
        "three.js's MIT notice is missing"
    rest = html
    for f in ("three.min.js", "examples/js/controls/OrbitControls.js"):
        text = (THREE / f).read_text()
        assert text in rest, f"{f} is not in the page unchanged"
        rest = rest.replace(text, "")
    for pattern in (r"https?:", r"\bsrc\s*=", r"\bhref\s*=", r"url\(", r"@import", r"\bfetch\s*\(", r"XMLHttpRequest",
                    r"\bimport\s*\(", r"WebSocket", r"EventSource", r"sendBeacon", r"\bWorker\s*\(",
                    r"<(link|iframe|img|object|embed|audio|video|source)\b"):
        m = re.search(pattern, rest)
        assert m is None, f"the page points elsewhere: {rest[max(0, m.start() - 60):m.end() + 60]!r}"


def test_a_dynamic_run_gives_every_frame_with_its_time_and_final_obj():
    out = simulate(scene())
    p = view(out)
    assert p.returncode == 0, p.stderr
    d = data(out / "view.html")
    # frames 0, 4, 8 steps, then final.obj at step 10
    assert [round(t, 12) for t in d["times"]] == [0.0, 0.04, 0.08, 0.1], d["times"]
    assert d["status"] == "ok" and d["dynamic"] and d["sphere"]["radius"] == 0.25, d["status"]
    assert d["vertices"] == 30 and d["hinges"] == 3 * 5 * 4 - 5 - 4, d["hinges"]  # interior edges of a 6 x 5 grid
    check_self_contained((out / "view.html").read_text())


def test_out_writes_the_page_elsewhere():
    out = simulate(scene())
    page = out.parent / "elsewhere.html"
    assert view(out, "--out", page).returncode == 0 and page.exists() and not (out / "view.html").exists()


def test_a_static_run_shows_one_frame():
    out = simulate(scene(solve={"mode": "static"}, effects={"gravity": {"g": [0, 0, -9.81]},
                         "stretching": {"model": "stvk"}, "bending": {"energy": "tan"},
                         "pins": {"vertices": [0, 6, 12, 18, 24]}}))
    assert view(out).returncode == 0
    d = data(out / "view.html")
    assert d["times"] == [0.0] and not d["dynamic"] and d["sphere"] is None, d["times"]


def test_a_failed_run_shows_its_frames_and_its_status():
    out = simulate(scene(solve={"mode": "dynamic", "dt": 0.01, "steps": 40, "max_newton": 2}))
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "failed" and not (out / "final.obj").exists(), summary
    assert view(out).returncode == 0
    d = data(out / "view.html")
    assert d["status"] == "failed" and d["reason"] == summary["reason"], d["status"]
    assert len(d["times"]) == len(os.listdir(out / "frames")) >= 1, d["times"]


def test_a_folder_that_is_not_a_runs_output_is_exit_1_naming_it():
    d = temporary_folder()
    for folder in (d, d / "missing"):
        p = view(folder)
        assert p.returncode == 1 and f"{folder}: not a simulation's output folder" in p.stderr, p.stderr
    assert not (d / "view.html").exists()


def test_frames_whose_vertex_counts_differ_are_exit_1_naming_the_frame_and_leave_no_page():
    out = simulate(scene())
    frame = out / "frames" / "00001.obj"
    frame.write_text(frame.read_text() + "v 9 9 9\n")
    p = view(out)
    assert p.returncode == 1 and f"{frame}: 31 vertices where rest.obj has 30" in p.stderr, p.stderr
    assert not (out / "view.html").exists() and not [f for f in os.listdir(out) if "view" in f], os.listdir(out)


def test_usage_errors_are_exit_2():
    assert view().returncode == 2
    assert view("a", "b").returncode == 2
    assert view("a", "--frames", "3").returncode == 2


if __name__ == "__main__":
    sys.exit(run_all(globals()))
