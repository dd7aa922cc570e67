#!/usr/bin/env python3
"""hinge view in a real browser: headless chromium (no GPU: SwiftShader's WebGL, and the 2D fallback) opens
the page of a short cloth-sphere run at 15 x 15 and draws a coloured mesh, another frame (#frame=N) draws
another picture, the 2D canvas draws it too, and nothing is fetched (the console logs no refused or failed
load; that nothing in the page points elsewhere is test_command.py's).

    test_browser.py HINGE SCENE.json [--keep DIR]

Label browser (release only); needs Debian's chromium (scripts/install-deps.sh --tests) and /usr/bin/python3's
numpy and matplotlib (to read the screenshots)."""
import json
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import matplotlib.image
import numpy as np

WIDTH, HEIGHT = 800, 600
BAR, PANEL = 90, 44  # page.css: the colour bar's column on the right, the controls' row at the bottom
CHROMIUM = ["chromium", "--headless=new", "--no-sandbox", "--disable-gpu", "--use-angle=swiftshader",
            "--enable-unsafe-swiftshader", "--enable-logging=stderr", "--v=0", f"--window-size={WIDTH},{HEIGHT}",
            "--virtual-time-budget=5000"]


def chromium(args, page, fragment):
    with tempfile.TemporaryDirectory() as profile:  # its own profile: no clash with another chromium
        r = subprocess.run(CHROMIUM + [f"--user-data-dir={profile}"] + args + [page.resolve().as_uri() + fragment],
                           capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    # The page's Content-Security-Policy forbids every fetch: an attempt would be logged as refused or failed.
    for line in r.stderr.splitlines():
        assert not re.search(r"Refused to|net::ERR_|Failed to load|Uncaught", line), line
    return r.stdout


def screenshot(page, fragment, png):
    """The 3D view's pixels, and the page's <body> tag once drawn (its data-renderer and data-frame)."""
    dom = chromium([f"--screenshot={png}", "--dump-dom"], page, fragment)
    image = matplotlib.image.imread(png)[..., :3]
    assert image.shape[:2] == (HEIGHT, WIDTH), image.shape
    return image[: HEIGHT - PANEL, : WIDTH - BAR], re.search(r"<body[^>]*>", dom).group(0)


def coloured_share(view):
    """The share of the view's pixels that are coloured: background, sphere and boundary are grey (chroma 0);
    every level of the colour scale has chroma above 0.3, above 0.15 once shaded."""
    return float(((view.max(axis=2) - view.min(axis=2)) > 0.15).mean())


def main():
    hinge, scene_file = sys.argv[1], Path(sys.argv[2])
    if shutil.which("chromium") is None:
        print("chromium not found: Debian's chromium is what this test needs (scripts/install-deps.sh --tests)")
        return 1
    keep = Path(sys.argv[4]) if len(sys.argv) > 4 and sys.argv[3] == "--keep" else None
    with tempfile.TemporaryDirectory() as tmp:
        work = keep or Path(tmp)
        scene = json.loads(scene_file.read_text())
        scene["mesh"]["grid"]["vertices"] = [15, 15]
        scene["solve"]["steps"] = 20  # to 0.2 s: the cloth has met the sphere
        scene["output"]["every"] = 5
        (work / "scene.json").write_text(json.dumps(scene))
        out = work / "out"
        subprocess.run([hinge, "simulate", str(work / "scene.json"), "--out", str(out), "--quiet", "--overwrite"],
                       check=True, capture_output=True, timeout=60)
        subprocess.run([hinge, "view", str(out)], check=True, capture_output=True, timeout=60)
        page = out / "view.html"

        start = time.monotonic()
        first, body0 = screenshot(page, "#frame=0", work / "frame0.png")
        last, body4 = screenshot(page, "#frame=4", work / "frame4.png")
        fallback, body2d = screenshot(page, "#frame=4&draw=2d", work / "frame4-2d.png")
        seconds = time.monotonic() - start

        # SwiftShader's WebGL drew frames 0 and 4, the 2D canvas frame 4.
        assert 'data-renderer="webgl"' in body0 and 'data-frame="0"' in body0, body0
        assert 'data-renderer="webgl"' in body4 and 'data-frame="4"' in body4, body4
        assert 'data-renderer="2d"' in body2d and 'data-frame="4"' in body2d, body2d
        shares = [coloured_share(v) for v in (first, last, fallback)]
        changed = float((np.abs(first - last).max(axis=2) > 0.1).mean())
        print(f"coloured: frame 0 {shares[0]:.1%}, frame 4 {shares[1]:.1%}, frame 4 on the 2D canvas {shares[2]:.1%}; "
              f"frames 0 and 4 differ in {changed:.1%} of the pixels; chromium {seconds:.1f} s")
        # The mesh must fill a good part of the view: 2% is the floor for this run.
        assert min(shares) >= 0.02, shares
        # Another frame, another picture: the cloth has fallen onto the sphere and bent between frames 0 and 4.
        assert changed >= 0.02, changed
    return 0


if __name__ == "__main__":
    sys.exit(main())
