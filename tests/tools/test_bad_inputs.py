#!/usr/bin/env python3
"""The bad-input catalogue (docs/testing.md, "Bad input"): every rejected input the tests try, across the
readers and the commands, with the message it gets and the exit status. One test per entry: the exit
status, the message (on standard error, or in the output line for hinge eval's per-line errors), no file
left in the folder but the inputs, and no NaN or infinity printed.

Usage: test_bad_inputs.py HINGE_BINARY TESTING_MD   run every entry, and check that TESTING_MD holds the
                                                   catalogue table as --markdown prints it
       test_bad_inputs.py HINGE_BINARY --markdown   print the table (paste it between the markers)
"""
import json
import os
import re
import subprocess
import sys
import tempfile

from script_tests import run_all

HINGE = sys.argv[1]

# Inputs the entries share.
HINGE_OK = "0.5 1 0.25  0 0 0  1 0 0  0.25 -1 0.5"
TWO_TRIANGLES = "v 0 0 0\nv 1 0 0\nv 0.5 1 0.25\nv 0.25 -1 0.5\nf 1 2 3\nf 2 1 4\n"
FOLDED = "v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 1 0\nf 1 2 3\nf 2 1 4\n"  # both triangles the same: theta = pi
MESH = ["hessian", "--energy", "tan", "--k", "1", "--out", "{d}/H.mtx", "--gradient", "{d}/G.txt", "--mesh"]
ORACLE_MESH = ["oracle", "--energy", "tan", "--k", "1", "--out", "{d}/H.mtx", "--mesh"]


def hinge_line(x, id_="h"):
    return json.dumps({"id": id_, "x": x}) + "\n"


X_OK = [float(v) for v in HINGE_OK.split()]


class Entry:
    def __init__(self, reader, what, argv, exit, message, files=None, stdin="", where="stderr"):
        self.reader, self.what, self.argv, self.exit, self.message = reader, what, argv, exit, message
        self.files, self.stdin, self.where = files or {}, stdin, where


E = Entry
ENTRIES = [
    # OBJ meshes (hinge hessian; hinge oracle --mesh and hinge conform --mesh read them the same way)
    E("OBJ", "a file that does not exist", MESH + ["{d}/missing.obj"], 1, "{d}/missing.obj:0: cannot open for reading"),
    E("OBJ", "an empty file", MESH + ["{d}/m.obj"], 1, "{d}/m.obj: the mesh has no faces", {"m.obj": ""}),
    E("OBJ", "vertices and no face", MESH + ["{d}/m.obj"], 1, "{d}/m.obj: the mesh has no faces",
      {"m.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\n"}),
    E("OBJ", "a lone triangle: no interior edge", MESH + ["{d}/m.obj"], 1,
      "{d}/m.obj: the mesh has no interior edge, so its bending energy is 0 whatever its shape",
      {"m.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"}),
    E("OBJ", "a coordinate `nan`", MESH + ["{d}/m.obj"], 1, "{d}/m.obj:1: non-finite coordinate 'nan'", {"m.obj": "v nan 0 0\n" + TWO_TRIANGLES}),
    E("OBJ", "a coordinate `inf`", MESH + ["{d}/m.obj"], 1, "{d}/m.obj:2: non-finite coordinate 'inf'", {"m.obj": "v 0 0 0\nv inf 0 0\n" + TWO_TRIANGLES}),
    E("OBJ", "a coordinate beyond double's range (`1e400`)", MESH + ["{d}/m.obj"], 1,
      "{d}/m.obj:1: coordinate '1e400' is outside the range of double", {"m.obj": "v 1e400 0 0\n" + TWO_TRIANGLES}),
    E("OBJ", "a vertex with two coordinates", MESH + ["{d}/m.obj"], 1, "{d}/m.obj:1: vertex line with 2 coordinates, need 3",
      {"m.obj": "v 1 2\n" + TWO_TRIANGLES}),
    E("OBJ", "a coordinate that is not a number", MESH + ["{d}/m.obj"], 1, "{d}/m.obj:1: malformed coordinate 'x'",
      {"m.obj": "v 1 2 x\n" + TWO_TRIANGLES}),
    E("OBJ", "a quadrilateral face", MESH + ["{d}/m.obj"], 1, "{d}/m.obj:5: face with 4 vertices; only triangles",
      {"m.obj": "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"}),
    E("OBJ", "a face index past the last vertex", MESH + ["{d}/m.obj"], 1, "{d}/m.obj:7: vertex index 9 out of range",
      {"m.obj": TWO_TRIANGLES + "f 1 2 9\n"}),
    E("OBJ", "a face index 0", MESH + ["{d}/m.obj"], 1, "{d}/m.obj:7: vertex index 0 in face",
      {"m.obj": TWO_TRIANGLES + "f 0 1 2\n"}),
    E("OBJ", "a relative index before the first vertex", MESH + ["{d}/m.obj"], 1, "{d}/m.obj:7: relative vertex index -9 out of range",
      {"m.obj": TWO_TRIANGLES + "f -9 1 2\n"}),
    E("OBJ", "a face index beyond 32 bits", MESH + ["{d}/m.obj"], 1, "{d}/m.obj:7: vertex index 99999999999 too large",
      {"m.obj": TWO_TRIANGLES + "f 1 2 99999999999\n"}),
    E("OBJ", "a face that repeats a vertex", MESH + ["{d}/m.obj"], 1, "face 2 (OBJ face 3) repeats a vertex",
      {"m.obj": TWO_TRIANGLES + "f 1 1 2\n"}),
    E("OBJ", "an edge in three faces (non-manifold)", MESH + ["{d}/m.obj"], 1, "is shared by 3 faces (non-manifold)",
      {"m.obj": TWO_TRIANGLES + "v 0.5 0.5 1\nf 1 2 5\n"}),
    E("OBJ", "two faces with the same directed edge (inconsistent orientation)", MESH + ["{d}/m.obj"], 1, "(inconsistent orientation)",
      {"m.obj": "v 0 0 0\nv 1 0 0\nv 0.5 1 0.25\nv 0.25 -1 0.5\nf 1 2 3\nf 1 2 4\n"}),
    E("OBJ", "a face of zero area", MESH + ["{d}/m.obj"], 1, "face 0 (OBJ face 1) (vertices 0, 1, 2) has zero area",
      {"m.obj": "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0.25 -1 0.5\nf 1 2 3\nf 2 1 4\n"}),
    E("OBJ", "a rest mesh with other faces", MESH + ["{d}/m.obj", "--rest", "{d}/r.obj"], 1,
      "the rest mesh must have the same vertices",
      {"m.obj": TWO_TRIANGLES, "r.obj": "v 0 0 0\nv 1 0 0\nv 0.5 1 0.25\nv 0.25 -1 0.5\nf 1 2 3\n"}),
    E("OBJ", "a hinge folded flat onto itself: the tan energy is infinite", MESH + ["{d}/m.obj", "--rest", "{d}/r.obj"],
      1, "the tan energy is infinite at theta = +-pi", {"m.obj": FOLDED, "r.obj": TWO_TRIANGLES}),
    E("OBJ", "the same, certified (hinge oracle --mesh)", ORACLE_MESH + ["{d}/m.obj", "--rest", "{d}/r.obj"],
      1, "the tan energy is infinite at theta = +-pi", {"m.obj": FOLDED, "r.obj": TWO_TRIANGLES}),
    E("OBJ", "an output folder that does not exist", ["hessian", "--energy", "tan", "--k", "1", "--out",
      "{d}/no/H.mtx", "--mesh", "{d}/m.obj"], 1, "cannot write {d}/no/H.mtx: No such file or directory",
      {"m.obj": TWO_TRIANGLES}),
    # hinge hessian's options
    E("options", "hessian without --mesh", ["hessian", "--energy", "tan", "--k", "1"], 2, "--mesh is required"),
    E("options", "an unknown energy", ["hessian", "--energy", "springs", "--k", "1", "--mesh", "{d}/m.obj"], 2, "springs",
      {"m.obj": TWO_TRIANGLES}),
    E("options", "a negative stiffness", ["hessian", "--energy", "tan", "--k", "-1", "--mesh", "{d}/m.obj"], 2,
      "--k: the bending stiffness k must be finite and >= 0, got -1", {"m.obj": TWO_TRIANGLES}),
    E("options", "both --k and a material", ["hessian", "--energy", "tan", "--k", "1", "--young", "1", "--mesh",
      "{d}/m.obj"], 2, "give either --k or --young/--poisson/--thickness, not both", {"m.obj": TWO_TRIANGLES}),
    E("options", "Poisson's ratio 0.7, outside (-1, 0.5]", ["hessian", "--energy", "tan", "--young", "1", "--poisson",
      "0.7", "--thickness", "0.1", "--mesh", "{d}/m.obj"], 2, "--poisson: Poisson's ratio nu must be in (-1, 0.5], got 0.7",
      {"m.obj": TWO_TRIANGLES}),
    E("options", "an unknown method", ["eval", "--method", "magic"], 2, "magic", stdin=hinge_line(X_OK)),
    E("options", "an unknown scalar type", ["eval", "--scalar", "float80"], 2, "float80", stdin=hinge_line(X_OK)),
    E("options", "MPFR below 2 bits", ["eval", "--scalar", "mpfr:1"], 2, "mpfr:1", stdin=hinge_line(X_OK)),
    # JSON Lines hinges (hinge eval; hinge oracle reads them the same way): one error line, the others go on
    E("JSON Lines", "a line that is not JSON", ["eval"], 0, "not valid JSON", stdin="not json\n", where="stdout"),
    E("JSON Lines", "a hinge with 11 coordinates", ["eval"], 0, '"x" must be an array of 12 numbers', stdin=hinge_line(X_OK[:11]),
      where="stdout"),
    E("JSON Lines", "no x", ["eval"], 0, 'missing "x"', stdin='{"id": "h"}\n', where="stdout"),
    E("JSON Lines", "a coordinate that is a string", ["eval"], 0, '"x"[0] is not a number',
      stdin=hinge_line(["0"] + X_OK[1:]), where="stdout"),
    E("JSON Lines", "a coordinate beyond double's range (`1e999`)", ["eval"], 0, "coordinate x0.x is not finite",
      stdin='{"id": "h", "x": [1e999, 1, 0.25, 0, 0, 0, 1, 0, 0, 0.25, -1, 0.5]}\n', where="stdout"),
    E("JSON Lines", "a hinge edge of zero length (x1 == x2)", ["eval"], 0,
      "degenerate hinge: the hinge edge has zero length (x1 == x2)",
      stdin=hinge_line(X_OK[:6] + X_OK[3:6] + X_OK[9:]), where="stdout"),
    E("JSON Lines", "an upper triangle of zero area", ["eval"], 0,
      "degenerate hinge: the upper triangle (x0, x1, x2) has zero area",
      stdin=hinge_line([2, 0, 0] + X_OK[3:]), where="stdout"),
    E("JSON Lines", "a lower triangle of zero area", ["eval"], 0,
      "degenerate hinge: the lower triangle (x3, x2, x1) has zero area",
      stdin=hinge_line(X_OK[:9] + [3, 0, 0]), where="stdout"),
    E("JSON Lines", "the certified oracle on a degenerate hinge", ["oracle"], 0,
      "degenerate hinge: the upper triangle (x0, x1, x2) has zero area",
      stdin=hinge_line([2, 0, 0] + X_OK[3:]), where="stdout"),
    E("JSON Lines", "an input file that does not exist", ["eval", "--input", "{d}/missing.jsonl", "--output", "{d}/o.jsonl"],
      1, "{d}/missing.jsonl"),
    E("JSON Lines", "an output folder that does not exist", ["eval", "--output", "{d}/no/o.jsonl"], 1,
      "cannot write {d}/no/o.jsonl: No such file or directory",
      stdin=hinge_line(X_OK)),
    # a candidate's results (hinge conform --candidate)
    E("candidate", "a results file that does not exist", ["conform", "--candidate", "{d}/missing.jsonl"], 2,
      "{d}/missing.jsonl"),
    E("candidate", "a line without a readable id", ["conform", "--candidate", "{d}/c.jsonl"], 2, "{d}/c.jsonl:1:",
      {"c.jsonl": "garbage without an id\n"}),
    E("candidate", "an empty results file: every case missing", ["conform", "--candidate", "{d}/c.jsonl"], 1,
      "FAIL well-shaped: 40 of 40 cases; worst case well-shaped/00-random: missing", {"c.jsonl": ""}, where="stdout"),
    # plugins (hinge conform --plugin)
    E("plugin", "a file that is not a shared library", ["conform", "--plugin", "{d}/p.so"], 2, "{d}/p.so",
      {"p.so": "not an ELF file\n"}),
    E("plugin", "a library without the symbol", ["conform", "--plugin", "{plugin}", "--symbol", "no_such_function"], 2,
      "has no symbol no_such_function"),
    # Matrix Market (hinge conform --mesh --hessian)
    E("Matrix Market", "a Hessian of the wrong size", ["conform", "--mesh", "{d}/m.obj", "--energy", "tan", "--hessian",
      "{d}/H.mtx", "--gradient", "{d}/G.txt"], 2, "expected a 12 x 12 matrix",
      {"m.obj": TWO_TRIANGLES, "H.mtx": "%%MatrixMarket matrix coordinate real symmetric\n3 3 1\n1 1 1\n",
       "G.txt": "0\n" * 12}),
    E("Matrix Market", "another header", ["conform", "--mesh", "{d}/m.obj", "--energy", "tan", "--hessian", "{d}/H.mtx",
      "--gradient", "{d}/G.txt"], 2, "expected %%MatrixMarket matrix coordinate real symmetric|general",
      {"m.obj": TWO_TRIANGLES, "H.mtx": "%%MatrixMarket matrix array real general\n12 12\n", "G.txt": "0\n" * 12}),
    E("Matrix Market", "a truncated entry list", ["conform", "--mesh", "{d}/m.obj", "--energy", "tan", "--hessian",
      "{d}/H.mtx", "--gradient", "{d}/G.txt"], 2, "entry 2 is unreadable or out of range",
      {"m.obj": TWO_TRIANGLES, "H.mtx": "%%MatrixMarket matrix coordinate real symmetric\n12 12 3\n1 1 1\n",
       "G.txt": "0\n" * 12}),
    # hinge study
    E("study", "an input file that does not exist", ["study", "--quick", "--no-mesh", "--no-plots", "--out", "{d}/s",
      "--input", "{d}/missing.jsonl"], 1, "{d}/missing.jsonl"),
    E("study", "an input line that is not a hinge", ["study", "--quick", "--no-mesh", "--no-plots", "--out", "{d}/s",
      "--input", "{d}/h.jsonl"], 1, "{d}/h.jsonl:2:", {"h.jsonl": hinge_line(X_OK) + "not json\n"}),
    E("study", "an unknown method", ["study", "--quick", "--out", "{d}/s", "--methods", "magic"], 2, "magic"),
    E("study", "an unknown scalar type", ["study", "--quick", "--out", "{d}/s", "--scalars", "float80"], 2, "float80"),
]

# No NaN anywhere, and no NaN or infinity in a JSON line; the conformance report's "inf" is the documented
# error of a missing result (docs/conformance.md, "The report").
NAN = re.compile(r"(?i)(?<![\w.'\"])-?nan(?![\w'\"])")  # a quoted 'nan' is the input, echoed
# The project's own candidate plugin (conformance/plugins/), beside the hinge binary's folder in the build tree.
PLUGIN = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(HINGE))), "conformance", "hinge_candidate_fast.so")


def fill(text, d):
    return text.replace("{d}", d).replace("{plugin}", PLUGIN)


def run_entry(e):
    """Runs entry e, checks it, and returns the message it got (the temporary folder removed from it)."""
    with tempfile.TemporaryDirectory() as d:
        for name, content in e.files.items():
            with open(os.path.join(d, name), "w") as f:
                f.write(content)
        p = subprocess.run([HINGE] + [fill(a, d) for a in e.argv], input=e.stdin, capture_output=True, text=True,
                           timeout=300)
        left = sorted(set(os.listdir(d)) - set(e.files))
        stream = p.stderr
        if e.where == "stdout":  # an output line's "error" decoded, or the report's lines
            stream = "\n".join(json.loads(l).get("error", l) if l.startswith("{") else l for l in p.stdout.splitlines())
        assert p.returncode == e.exit, f"exit {p.returncode}, expected {e.exit}: {p.stderr.strip()}"
        assert fill(e.message, d) in stream, f"expected {fill(e.message, d)!r} in {stream.strip()!r}"
        assert not left, f"left behind: {left}"
        for line in p.stdout.splitlines():
            if line.startswith("{"):
                json.loads(line, parse_constant=lambda c: (_ for _ in ()).throw(AssertionError(f"{c} printed")))
            else:
                assert not NAN.search(line), f"a NaN printed: {line}"
        assert not NAN.search(p.stderr), f"a NaN printed: {p.stderr}"
        shown = next(l for l in stream.splitlines() if fill(e.message, d) in l)
        return shown.replace(d + "/", "").replace(os.path.dirname(PLUGIN) + "/", "").strip()


MESSAGES = {}  # entry number -> the message it got, from its test (so that the docs check runs nothing again)


def markdown():
    rows = ["| # | reader or command | input | exit | message |", "| ---: | --- | --- | ---: | --- |"]
    for i, e in enumerate(ENTRIES, 1):
        message = (MESSAGES[i] if i in MESSAGES else run_entry(e)).replace("|", "\\|")
        where = " (standard output)" if e.where == "stdout" else ""
        rows.append(f"| {i} | {e.reader} | {e.what} | {e.exit} | `{message}`{where} |")
    return "\n".join(rows) + "\n"


def make_test(i, e):
    def test():
        MESSAGES[i] = run_entry(e)
    return test


tests = {f"test_{i:02d}_{re.sub(r'[^a-z0-9]+', '_', (e.reader + ' ' + e.what).lower()).strip('_')}": make_test(i, e)
         for i, e in enumerate(ENTRIES, 1)}


def test_the_catalogue_in_testing_md_is_this_one():  # runs last: the entries' messages are known by then
    with open(sys.argv[2]) as f:
        text = f.read()
    begin, end = "<!-- bad-inputs: begin -->\n", "<!-- bad-inputs: end -->"
    assert begin in text and end in text, "markers missing in " + sys.argv[2]
    assert text.split(begin)[1].split(end)[0] == markdown(), "docs/testing.md's catalogue differs: paste --markdown"


if __name__ == "__main__":
    if sys.argv[2] == "--markdown":
        sys.stdout.write(markdown())
        sys.exit(0)
    tests["test_the_catalogue_in_testing_md_is_this_one"] = test_the_catalogue_in_testing_md_is_this_one
    sys.exit(run_all(tests))
