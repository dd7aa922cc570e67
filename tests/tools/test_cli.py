#!/usr/bin/env python3
"""The `hinge` command against docs/contract.md: formats, per-line errors, exit statuses, output files.

Usage: test_cli.py HINGE_BINARY EXAMPLES_DIR (docs/examples). Each check is a function test_*; script_tests.run_all runs them all,
prints one line per check and "N passed, M failed", and exits nonzero if any failed.
"""
import json
import math
import os
import subprocess
import sys
import tempfile

from script_tests import run_all

HINGE, EXAMPLES = sys.argv[1], sys.argv[2]


def run(args, stdin="", env=None, timeout=120):
    p = subprocess.run([HINGE] + args, input=stdin, capture_output=True, text=True, timeout=timeout, env=env)
    return p.returncode, p.stdout, p.stderr


def lines(text):
    return [json.loads(l) for l in text.splitlines() if l.strip()]


def test_version_names_the_contract():
    code, out, _ = run(["--version"])
    assert code == 0 and "contract version 3" in out, out


def test_every_command_has_help():
    for cmd in ["eval", "oracle", "hessian", "conform", "study", "simulate", "view", "demo"]:
        code, out, _ = run([cmd, "--help"])
        assert code == 0 and "--" in out, (cmd, code)


def test_oracle_reproduces_the_worked_examples_exactly():
    with open(os.path.join(EXAMPLES, "eval-input.jsonl")) as f:
        code, out, _ = run(["oracle"], f.read())
    assert code == 0
    want = lines(open(os.path.join(EXAMPLES, "oracle-output.jsonl")).read())
    got = lines(out)
    assert [g["id"] for g in got] == [w["id"] for w in want]
    for g, w in zip(got, want):
        for k in ("theta", "grad", "hess"):
            assert g[k] == w[k], (w["id"], k)


def test_eval_double_is_within_a_few_units_of_the_oracle():
    text = open(os.path.join(EXAMPLES, "eval-input.jsonl")).read()
    got, want = lines(run(["eval"], text)[1]), lines(open(os.path.join(EXAMPLES, "oracle-output.jsonl")).read())
    for g, w in zip(got, want):
        num = math.sqrt(sum((a - b) ** 2 for a, b in zip(g["hess"], w["hess"])))
        den = math.sqrt(sum(b * b for b in w["hess"]))
        assert num / den <= 8 * 2.0**-53, (w["id"], num / den / 2.0**-53)  # the bound for double


def test_cond_gives_the_tolerance_policy_condition_numbers():
    # The committed conformance vectors hold each case's certified values, L and kappa (docs/conformance.md).
    vectors_dir = os.path.join(os.path.dirname(EXAMPLES), "..", "conformance", "hinges")
    for category in ("short-hinge-edges", "needles", "near-flat"):
        with open(os.path.join(vectors_dir, category + ".jsonl")) as f:
            text = f.read()
        want = lines(text)
        for method in ("fast", "reference"):
            code, out, _ = run(["eval", "--method", method, "--cond"], text)
            got = lines(out)
            assert code == 0 and [g["id"] for g in got] == [w["id"] for w in want]
            for g, w in zip(got, want):
                assert g["kappa"] == dict(zip(("theta", "grad", "hess"), w["kappa"])), w["id"]
                assert all(math.isfinite(k) and k > 0 for k in g["kappa"].values()), w["id"]
                # kappa_theta = L ||grad theta|| / |theta|, recomputed here from the certified values: the two
                # evaluations of that formula in double differ by their roundings (about 16 operations), 32 ulps.
                if w["theta"] != 0:
                    independent = w["length"] * math.sqrt(sum(v * v for v in w["grad"])) / abs(w["theta"])
                    assert abs(g["kappa"]["theta"] - independent) <= 32 * 2.0**-53 * independent, w["id"]
        kappas = [g["kappa"]["hess"] for g in got]
        if category != "near-flat":  # hard cases are ill-conditioned: kappa grows as the shape degenerates
            assert max(kappas) > 1e9, (category, max(kappas))
    code, out, _ = run(["eval", "--cond"], '{"id": "degenerate", "x": [0,0,0, 1,0,0, 1,0,0, 0,1,0]}\n')
    assert code == 0 and "kappa" not in lines(out)[0] and "error" in lines(out)[0]


def test_faithful_is_within_one_unit_of_the_certified_values_in_every_category():
    # The contract: --faithful within 1 unit of 2^-53 of the certified values, normwise per output group
    # (the committed vectors hold them), in every category; and only with --method fast --scalar double.
    vectors_dir = os.path.join(os.path.dirname(EXAMPLES), "..", "conformance", "hinges")
    names = sorted(n for n in os.listdir(vectors_dir) if n.endswith(".jsonl"))
    assert len(names) >= 9, names
    for name in names:
        with open(os.path.join(vectors_dir, name)) as f:
            text = f.read()
        want = lines(text)
        code, out, _ = run(["eval", "--method", "fast", "--faithful"], text)
        got = lines(out)
        assert code == 0 and [g["id"] for g in got] == [w["id"] for w in want], name
        for g, w in zip(got, want):
            for k in ("theta", "grad", "hess"):
                have, certified = (g[k], w[k]) if k != "theta" else ([g[k]], [w[k]])
                num = math.sqrt(sum((a - b) ** 2 for a, b in zip(have, certified)))
                den = math.sqrt(sum(b * b for b in certified))
                assert num <= 2.0**-53 * den, (w["id"], k, num / den / 2.0**-53 if den else num)
    alone = run(["eval", "--faithful"], text)  # without --method: fast
    assert alone[0] == 0 and alone[1] == run(["eval", "--method", "fast", "--faithful"], text)[1]
    for wrong in (["--method", "reference"], ["--method", "fast", "--scalar", "long-double"]):
        code, _, err = run(["eval", "--faithful"] + wrong, "")
        assert code == 2 and "--faithful" in err, (wrong, code, err)


def run_with_isa(isa, args, stdin=""):
    return run(args, stdin, env=dict(os.environ, HINGE_ISA=isa), timeout=300)


def test_hinge_isa_selects_the_double_kernels_with_the_same_bits_and_rejects_unknown_values():
    text = open(os.path.join(EXAMPLES, "eval-input.jsonl")).read()
    mesh = os.path.join(os.path.dirname(EXAMPLES), "..", "conformance", "meshes", "hex.obj")
    rest = os.path.join(os.path.dirname(EXAMPLES), "..", "conformance", "meshes", "hex-rest.obj")
    outputs = {}
    with tempfile.TemporaryDirectory() as d:
        for isa in ("avx512", "avx2", "baseline", ""):  # "" is unset: the best the processor has
            code, out, err = run_with_isa(isa, ["eval", "--method", "fast"], text)
            if code == 2 and "lacks" in err:  # a processor without it: the error names HINGE_ISA and the set
                assert isa in ("avx512", "avx2") and "HINGE_ISA=" + isa in err, err
                continue
            hessian = os.path.join(d, isa + "H.mtx")
            code2, energy, _ = run_with_isa(isa, ["hessian", "--mesh", mesh, "--rest", rest, "--energy", "tan", "--k", "1",
                                                  "--method", "fast", "--out", hessian])
            assert code == 0 and code2 == 0, (isa, err)
            outputs[isa] = (out, energy, open(hessian).read())
    assert "baseline" in outputs and len(set(outputs.values())) == 1, list(outputs)
    code, _, err = run_with_isa("sse9", ["eval", "--method", "fast"], text)
    assert code == 2 and "HINGE_ISA=sse9" in err, (code, err)
    # A mesh large enough for the face pass to run on two threads: the variable is read on the caller's.
    with tempfile.TemporaryDirectory() as d:
        grid = os.path.join(d, "grid.obj")
        n = 50
        with open(grid, "w") as f:
            for j in range(n):
                for i in range(n):
                    f.write("v %r %r %r\n" % (i / n, j / n, 0.002 * ((7 * i + 3 * j) % 5)))
            for j in range(n - 1):
                for i in range(n - 1):
                    a = j * n + i + 1
                    f.write("f %d %d %d\nf %d %d %d\n" % (a, a + 1, a + n + 1, a, a + n + 1, a + n))
        code, _, err = run_with_isa("sse9", ["hessian", "--mesh", grid, "--energy", "tan", "--k", "1", "--method", "fast",
                                             "--threads", "2", "--out", os.path.join(d, "H.mtx")])
        assert code == 2 and "HINGE_ISA=sse9" in err, (code, err)
    assert run_with_isa("sse9", ["eval", "--method", "reference"], text)[0] == 0  # only the double kernels read it


def test_numbers_read_back_exactly_and_look_like_doubles():
    code, out, _ = run(["eval", "--scalar", "bin128"], open(os.path.join(EXAMPLES, "eval-input.jsonl")).read())
    assert code == 0
    for token in out.replace("[", " ").replace("]", " ").replace(",", " ").split():
        if token[0] in "-0123456789":
            mantissa = token.split("e")[0].replace("-", "").replace(".", "").lstrip("0")
            assert len(mantissa) <= 17 and math.isfinite(float(token)), token  # shortest round trip


def test_invalid_lines_get_line_numbers_and_keep_readable_ids():
    stdin = "\n".join([
        '{"id": "ok", "x": [0.5,1,0,0,0,0,1,0,0,0.5,-1,0]}',
        "not json",
        "",
        '{"id": "short", "x": [1,2,3]}',
        '{"id": "degenerate", "x": [0.5,1,0,0,0,0,0,0,0,0.5,-1,0]}',
        '{"id": "nonfinite", "x": [1e400,1,0,0,0,0,1,0,0,0.5,-1,0]}',
        '{"x": [0.5,1,0,0,0,0,1,0,0,0.5,-1,0]}',
    ]) + "\n"
    code, out, _ = run(["eval"], stdin)
    assert code == 0
    got = lines(out)
    assert len(got) == 6
    assert got[0]["id"] == "ok" and got[0]["theta"] == 0.0
    assert got[1] == {"id": None, "line": 2, "error": got[1]["error"]}
    assert got[2]["id"] == "short" and got[2]["line"] == 4
    assert got[3]["id"] == "degenerate" and "error" in got[3] and "line" not in got[3]
    assert got[4]["id"] == "nonfinite" and "error" in got[4]
    assert got[5]["id"] is None and got[5]["line"] == 7


def test_branch_cut_is_plus_pi():
    x = [0.5, 1, 0, 0, 0, 0, 1, 0, 0, 0.25, 2, 0]
    out = lines(run(["eval"], json.dumps({"id": "folded", "x": x}))[1])
    assert out[0]["theta"] == math.pi


def test_usage_errors_exit_2():
    assert run(["eval", "--scalar", "quad"])[0] == 2
    assert run(["eval", "--method", "symbolc"])[0] == 2  # misspelt
    assert run(["frobnicate"])[0] == 2
    assert run(["hessian"])[0] == 2  # --mesh is required


def two_triangles(path, z=0.25):
    with open(path, "w") as f:
        f.write(f"v 0 0 0\nv 1 0 0\nv 0.5 1 {z}\nv 0.5 -1 0\nf 3 1 2\nf 4 2 1\n")


def test_hessian_writes_matrix_market_and_gradient():
    with tempfile.TemporaryDirectory() as d:
        rest, mesh = os.path.join(d, "rest.obj"), os.path.join(d, "mesh.obj")
        two_triangles(rest, 0.0)
        two_triangles(mesh, 0.25)
        H, G = os.path.join(d, "H.mtx"), os.path.join(d, "G.txt")
        code, out, err = run(["hessian", "--mesh", mesh, "--rest", rest, "--energy", "tan", "--k", "1",
                              "--out", H, "--gradient", G])
        assert code == 0, err
        assert out.startswith("energy ") and float(out.split()[1]) > 0
        mm = open(H).read().splitlines()
        assert mm[0] == "%%MatrixMarket matrix coordinate real symmetric"
        size = [l for l in mm if not l.startswith("%")][0].split()
        assert size[0] == size[1] == "12"
        entries = [l.split() for l in mm if not l.startswith("%")][1:]
        assert len(entries) == int(size[2]) and all(int(i) >= int(j) for i, j, _ in entries)
        assert len(open(G).read().split()) == 12
        assert sorted(os.listdir(d)) == ["G.txt", "H.mtx", "mesh.obj", "rest.obj"]


def test_young_poisson_thickness_give_equation_eleven():
    with tempfile.TemporaryDirectory() as d:
        rest, mesh = os.path.join(d, "rest.obj"), os.path.join(d, "mesh.obj")
        two_triangles(rest, 0.0)
        two_triangles(mesh, 0.25)
        e1 = run(["hessian", "--mesh", mesh, "--rest", rest, "--energy", "shells", "--k", str(1 / 6)])[1]
        e2 = run(["hessian", "--mesh", mesh, "--rest", rest, "--energy", "shells",
                  "--young", "24", "--poisson", "0.5", "--thickness", "0.5"])[1]
        assert e1 == e2, (e1, e2)
        assert run(["hessian", "--mesh", mesh, "--energy", "shells", "--k", "1", "--young", "2"])[0] == 2


def test_invalid_mesh_exits_1_naming_the_problem_and_leaves_no_file():
    with tempfile.TemporaryDirectory() as d:
        bad = os.path.join(d, "bad.obj")
        with open(bad, "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 1 2 4\n")  # directed edge 1->2 twice
        H = os.path.join(d, "H.mtx")
        code, _, err = run(["hessian", "--mesh", bad, "--energy", "tan", "--k", "1", "--out", H])
        assert code == 1 and "face" in err, err
        assert os.listdir(d) == ["bad.obj"]
        with open(bad, "w") as f:
            f.write("v 0 0 0\nv 1 zero 0\n")
        code, _, err = run(["hessian", "--mesh", bad, "--energy", "tan", "--k", "1"])
        assert code == 1 and "bad.obj:2" in err, err


def test_a_mesh_with_no_faces_exits_1_naming_the_file_for_every_mesh_command():
    # docs/contract.md, version 2: an empty file, or one with vertices and no faces, is not a mesh.
    with tempfile.TemporaryDirectory() as d:
        empty, faceless = os.path.join(d, "empty.obj"), os.path.join(d, "faceless.obj")
        open(empty, "w").close()
        with open(faceless, "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\n")
        H = os.path.join(d, "H.mtx")
        for mesh in [empty, faceless]:
            for command in [["hessian"], ["oracle"]]:
                code, out, err = run(command + ["--mesh", mesh, "--energy", "tan", "--k", "1", "--out", H])
                assert code == 1 and mesh in err and "no faces" in err, (command, code, err)
                assert not os.path.exists(H) and "nan" not in out.lower(), command
            code, _, err = run(["conform", "--mesh", mesh, "--energy", "tan", "--hessian", H])
            assert code == 1 and mesh in err and "no faces" in err, (code, err)


def test_threads_and_repeat_do_not_change_output():
    with tempfile.TemporaryDirectory() as d:
        rest, mesh = os.path.join(d, "rest.obj"), os.path.join(d, "mesh.obj")
        two_triangles(rest, 0.0)
        two_triangles(mesh, 0.25)
        outs = []
        for extra in (["--threads", "1"], ["--threads", "2", "--repeat", "3"]):
            H = os.path.join(d, "H%d.mtx" % len(outs))
            run(["hessian", "--mesh", mesh, "--rest", rest, "--energy", "tan", "--k", "1", "--out", H] + extra)
            outs.append(open(H).read())
        assert outs[0] == outs[1]


if __name__ == "__main__":
    sys.exit(run_all(globals()))
