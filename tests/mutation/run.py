#!/usr/bin/python3
"""Mutation check of the property suite (docs/testing.md, "Mutation check").

Applies deliberate defects to the sources one at a time, rebuilds the `properties` executable, runs it,
and records which properties kill each mutant (fail where the unmutated build passes). Prints the table
of docs/testing.md; --update-docs writes it there between the markers.

The sources are never mutated in place: the script copies the project's source folders to
build/mutation/src (others may be building from the working tree at the same time), mutates the copy one
file at a time, and restores each file from its saved original in a `finally` block (also on an
interrupt). Builds go to build/mutation/build. RapidCheck runs with a fixed seed, so the table is
reproducible; HINGE_TEST_DEPTH is left at quick.

Usage: tests/mutation/run.py [--only ID[,ID...]] [--jobs N] [--seed S] [--update-docs] [--keep-going]
"""

import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
WORK = ROOT / "build" / "mutation"
SRC = WORK / "src"
BUILD = WORK / "build"
DOCS = ROOT / "docs" / "testing.md"
BEGIN, END = "<!-- mutation-table: begin (tests/mutation/run.py --update-docs) -->", "<!-- mutation-table: end -->"

# Source folders and files copied to the private tree (everything CMake may need to configure).
COPIED = ["CMakeLists.txt", "CMakePresets.json", "cmake", "core", "reference", "io", "fast", "oracle", "methods", "proofs", "tools",
          "tests", "bench", "conformance", "docs"]


class Mutant:
    """One defect: in `path`, each (old, new) replacement applied once (old must occur exactly once)."""

    def __init__(self, ident, path, what, edits):
        self.ident, self.path, self.what, self.edits = ident, path, what, edits


MUTANTS = [
    # --- hinge::reference -------------------------------------------------------------------------------
    Mutant("ref-omega", "reference/include/hinge/reference/hessian.hpp",
           "Q~ with omega instead of omega~ (the upper triangle's altitudes in the lower blocks H33, H13, H23)",
           [("block(3, 3) = -S(bt.Q(0));", "block(3, 3) = -S(Mat3<Scalar>(b.omega(0, 0) * bt.M(0)));"),
            ("block(1, 3) = bt.P(1, 0) - bt.Q(1);", "block(1, 3) = bt.P(1, 0) - b.omega(0, 1) * bt.M(1);"),
            ("block(2, 3) = bt.P(2, 0) - bt.Q(2);", "block(2, 3) = bt.P(2, 0) - b.omega(0, 2) * bt.M(2);")]),
    Mutant("ref-p12", "reference/include/hinge/reference/hessian.hpp",
           "P12 and P21 swapped in H12",
           [("block(1, 2) = b.P(1, 2) + b.P(2, 1).transpose() + bt.P(1, 2) + bt.P(2, 1).transpose() + N0_and_Nt0;",
             "block(1, 2) = b.P(2, 1) + b.P(1, 2).transpose() + bt.P(2, 1) + bt.P(1, 2).transpose() + N0_and_Nt0;")]),
    Mutant("ref-sign", "reference/include/hinge/reference/bend_angle.hpp",
           "theta's sign flipped",
           [("b.theta = atan2(y, x);", "b.theta = -atan2(y, x);")]),
    Mutant("ref-acos", "reference/include/hinge/reference/bend_angle.hpp",
           "theta by acos(n . n~) with the sign of the numerator, instead of atan2",
           [("b.theta = atan2(y, x);",
             "{ using std::acos; b.theta = acos(s.upper.n.dot(s.lower.n)); if (y < 0) b.theta = -b.theta; }")]),
    Mutant("ref-psi2", "reference/include/hinge/reference/hinge_energy.hpp",
           "the psi'' grad theta grad theta^T term of eq. (3) dropped",
           [("return p.d1 * hess_theta + p.d2 * grad_theta * grad_theta.transpose();",
             "return p.d1 * hess_theta + 0 * p.d2 * grad_theta * grad_theta.transpose();")]),
    # --- hinge::fast --------------------------------------------------------------------------------------
    Mutant("fast-dagger-neither", "fast/src/triangle_kernel.hpp",
           "eq. (7): R (N0) transposed in neither half-hinge",
           [("const bool transpose = (dagger >> k) & 1u,", "const bool transpose = ((dagger >> k) & 1u) && false,")]),
    Mutant("fast-dagger-both", "fast/src/triangle_kernel.hpp",
           "eq. (7): R (N0) transposed in both half-hinges",
           [("const bool transpose = (dagger >> k) & 1u,", "const bool transpose = ((dagger >> k) & 1u) || true,")]),
    Mutant("fast-sigma", "fast/src/passes.hpp",
           "sigma dropped: a boundary edge takes c_i = psi' of hinge 0 instead of 0",
           [("c[i] = F.hinge[i] >= 0 ? psi1[F.hinge[i]] : Scalar(0);",
             "c[i] = psi1[F.hinge[i] >= 0 ? F.hinge[i] : 0];")]),
    Mutant("fast-skip-edge", "fast/src/passes.hpp",
           "the combined loop skips local edge 2 of every face (its owned hinge's terms)",
           [("for (int k = 0; k < 3; ++k) {\n      if (!((F.owns >> k) & 1u)) continue;",
             "for (int k = 0; k < 2; ++k) {\n      if (!((F.owns >> k) & 1u)) continue;")]),
    Mutant("fast-p12", "fast/src/generic_kernel.hpp",
           "per-hinge kernel: P12 and P21 swapped in H12 (P21 + P12^T = H12^T: the blocks H12, H21 exchanged)",
           [("store<Scalar>(at(1, 2, c),", "store<Scalar>(at(9, 9, c),"),
            ("store<Scalar>(at(2, 1, c),", "store<Scalar>(at(1, 2, c),"),
            ("store<Scalar>(at(9, 9, c),", "store<Scalar>(at(2, 1, c),")]),
    Mutant("fast-sign", "fast/src/generic_kernel.hpp",
           "per-hinge kernel: theta's sign flipped",
           [("out.theta = sign < 0 ? Scalar(-t) : t;", "out.theta = sign < 0 ? t : Scalar(-t);")]),
    Mutant("fast-mesh-sign", "fast/src/passes.hpp",
           "mesh assembly: theta's sign flipped (the models that use theta itself)",
           [("b.theta = sign < 0 ? Scalar(-theta) : theta;", "b.theta = sign < 0 ? theta : Scalar(-theta);")]),
]


def log(*args):
    print(*args, file=sys.stderr, flush=True)


def copy_tree():
    """A fresh private copy of the sources (no build directories, no .git)."""
    if SRC.exists():
        shutil.rmtree(SRC)
    SRC.mkdir(parents=True)
    ignore = shutil.ignore_patterns("build", "build-*", ".git", "__pycache__")
    for name in COPIED:
        p = ROOT / name
        if p.is_dir():
            shutil.copytree(p, SRC / name, ignore=ignore)
        elif p.is_file():
            shutil.copy2(p, SRC / name)


def configure():
    # -O1: each mutant rebuilds the libraries' multiprecision instantiations; at -O1 they compile in about
    # half the time, and the properties check values, not speed.
    args = ["cmake", "-S", str(SRC), "-B", str(BUILD), "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG",
            "-DHINGE_WARNINGS_AS_ERRORS=OFF", "-DHINGE_BUILD_TOOLS=OFF", "-DHINGE_BUILD_BENCHMARKS=OFF"]
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit("configure failed:\n" + r.stdout + r.stderr)


def build(jobs):
    r = subprocess.run(["cmake", "--build", str(BUILD), "-j", str(jobs), "--target", "properties"],
                       capture_output=True, text=True)
    return r.returncode == 0, r.stdout[-4000:] + r.stderr[-4000:]


def run_properties(seed, timeout):
    """Runs the property executable: (set of failed tests, set of passed tests, note)."""
    exe = BUILD / "tests" / "properties" / "properties"
    out = WORK / "result.json"
    if out.exists():
        out.unlink()
    env = dict(os.environ, RC_PARAMS=f"seed={seed}", HINGE_TEST_DEPTH="quick")
    env.pop("HINGE_TEST_MEASURE", None)
    note = ""
    try:
        r = subprocess.run([str(exe), f"--gtest_output=json:{out}"], capture_output=True, text=True, env=env,
                           timeout=timeout)
        text = r.stdout + r.stderr
        if r.returncode < 0:
            note = f"crashed (signal {-r.returncode})"
    except subprocess.TimeoutExpired as e:
        text = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        note = f"timed out after {timeout} s"
    failed, passed = set(), set()
    if out.exists():
        data = json.loads(out.read_text())
        for suite in data.get("testsuites", []):
            for t in suite.get("testsuite", []):
                name = f"{suite['name']}.{t['name']}"
                if t.get("status") != "RUN":
                    continue
                (failed if t.get("failures") else passed).add(name)
    else:  # crashed or timed out: the test that was running is the killer; parse the console
        current = None
        for line in text.splitlines():
            if line.startswith("[ RUN      ] "):
                current = line[len("[ RUN      ] "):].strip()
            elif line.startswith("[       OK ] "):
                passed.add(line[len("[       OK ] "):].split(" (")[0].strip())
                current = None
            elif line.startswith("[  FAILED  ] ") and "(" in line:
                failed.add(line[len("[  FAILED  ] "):].split(" (")[0].strip())
                current = None
        if current:
            failed.add(current + (" (crashed)" if "crashed" in note else " (timed out)"))
    return failed, passed, note


def apply(mutant):
    path = SRC / mutant.path
    text = path.read_text()
    for old, new in mutant.edits:
        count = text.count(old)
        if count != 1:
            raise RuntimeError(f"{mutant.ident}: expected exactly one occurrence of {old!r} in {mutant.path}, "
                               f"found {count} (the source changed: update the mutant)")
        text = text.replace(old, new)
    path.write_text(text)


def table(rows):
    lines = ["| mutant | file | defect | result | properties that fail (count: names) |",
             "| --- | --- | --- | --- | --- |"]
    for r in rows:
        names = ", ".join(f"`{k}`" for k in sorted(r["killers"]))
        killers = f"{len(r['killers'])}: {names}" if names else "—"
        lines.append(f"| `{r['id']}` | `{r['path']}` | {r['what']} | {r['status']} | {killers} |")
    return "\n".join(lines)


def update_docs(text):
    doc = DOCS.read_text()
    if BEGIN not in doc or END not in doc:
        sys.exit(f"{DOCS} lacks the markers {BEGIN!r} ... {END!r}")
    head, rest = doc.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    DOCS.write_text(head + BEGIN + "\n" + text + "\n" + END + tail)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", help="comma-separated mutant ids")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--seed", type=int, default=20130701)
    ap.add_argument("--timeout", type=int, default=900, help="seconds per run of the property executable")
    ap.add_argument("--update-docs", action="store_true")
    ap.add_argument("--keep-going", action="store_true", help="continue after a mutant that does not compile")
    args = ap.parse_args()

    mutants = MUTANTS
    if args.only:
        wanted = set(args.only.split(","))
        mutants = [m for m in MUTANTS if m.ident in wanted]
        unknown = wanted - {m.ident for m in mutants}
        if unknown:
            sys.exit(f"unknown mutant ids: {', '.join(sorted(unknown))}")

    # An interrupt or SIGTERM unwinds through the finally blocks below (the copy is restored).
    signal.signal(signal.SIGTERM, lambda *_: (_ for _ in ()).throw(KeyboardInterrupt()))

    WORK.mkdir(parents=True, exist_ok=True)
    log(f"copying the sources to {SRC}")
    copy_tree()
    configure()
    log("baseline build")
    ok, output = build(args.jobs)
    if not ok:
        sys.exit("the unmutated sources do not build:\n" + output)
    base_failed, base_passed, note = run_properties(args.seed, args.timeout)
    log(f"baseline: {len(base_passed)} properties pass, {len(base_failed)} fail {sorted(base_failed)} {note}")

    rows = []
    for m in mutants:
        path = SRC / m.path
        original = tempfile.NamedTemporaryFile(delete=False, dir=WORK, prefix="original-", suffix=path.suffix)
        original.write(path.read_bytes())
        original.close()
        started = time.time()
        try:
            apply(m)
            log(f"[{m.ident}] {m.what}: building")
            ok, output = build(args.jobs)
            if not ok:
                status, killers = "did not compile", set()
                log(output)
                if not args.keep_going:
                    raise RuntimeError(f"mutant {m.ident} does not compile")
            else:
                failed, _, note = run_properties(args.seed, args.timeout)
                killers = {t for t in failed if t.split(" (")[0] not in base_failed}
                status = ("**killed**" if killers else "SURVIVED") + (f" ({note})" if note else "")
        finally:
            shutil.copyfile(original.name, path)  # restore the original, whatever happened
            os.unlink(original.name)
        rows.append({"id": m.ident, "path": m.path, "what": m.what, "status": status, "killers": killers})
        log(f"[{m.ident}] {status} in {time.time() - started:.0f} s: {sorted(killers)}")

    log("restoring the build to the unmutated sources")
    build(args.jobs)
    text = table(rows)
    if base_failed:
        text += ("\n\nFailing already without a mutant (not counted as kills): " +
                 ", ".join(f"`{t}`" for t in sorted(base_failed)) + ".")
    print(text)
    if args.update_docs:
        update_docs(text)
    survivors = [r["id"] for r in rows if not r["killers"]]
    sys.exit(1 if survivors else 0)


if __name__ == "__main__":
    main()
