#!/usr/bin/env python3
"""hinge simulate as a user meets it (docs/contract.md 6.2): the outputs and their keys, only the effects a
scene names, strict scenes (exit 1, the message names the key, no final.obj), an earlier --out (exit 2
unless --overwrite), a run that cannot go on (exit 1, "status": "failed" with the reason), --threads
changing no output bit, the shipped scenes run (one step of each dynamic one).

Usage: test_simulate.py HINGE_BINARY SCENES_DIR
"""
import json
import os
import subprocess
import sys
import tempfile

from script_tests import run_all

HINGE, SCENES = sys.argv[1], sys.argv[2]


def scene(**overrides):
    s = {"scene": 1, "name": "t",
         "mesh": {"grid": {"vertices": [6, 5], "size": [0.5, 0.4], "center": [0, 0, 1], "plane": "xy"}},
         "material": {"density": 400, "young": 2e6, "poisson": 0.3, "thickness": 0.0005},
         "solve": {"mode": "dynamic", "dt": 0.01, "steps": 12},
         "effects": {"gravity": {"g": [0, 0, -9.81]}},
         "output": {"every": 4}}
    s.update(overrides)
    return s


def simulate(s, *extra, out_exists=False, text=None, env=None):
    d = tempfile.mkdtemp(prefix="hinge-simulate-")
    path = os.path.join(d, "scene.json")
    with open(path, "w") as f:
        f.write(text if text is not None else json.dumps(s))
    out = os.path.join(d, "out")
    if out_exists:
        os.makedirs(out)
        open(os.path.join(out, "summary.json"), "w").write("{}")
    p = subprocess.run([HINGE, "simulate", path, "--out", out, "--quiet", *extra], capture_output=True, text=True,
                       env=env)
    return p, out


def read_obj(path):
    with open(path) as f:
        return [tuple(float(t) for t in line.split()[1:]) for line in f if line.startswith("v ")]


def test_gravity_alone_runs_gravity_alone():
    p, out = simulate(scene())
    assert p.returncode == 0, p.stderr
    s = json.load(open(os.path.join(out, "summary.json")))
    assert s["status"] == "ok" and s["effects"] == ["gravity"], s
    assert list(s["time_s"]["effects"]) == ["gravity"] and list(s["energy"]) == ["gravity"], s
    assert s["steps"] == 12 and s["vertices"] == 30 and s["bending_share"] == 0, s
    assert {"version", "commit", "compiler", "flags"} <= set(s["build"]), s
    assert sorted(os.listdir(os.path.join(out, "frames"))) == ["00000.obj", "00001.obj", "00002.obj", "00003.obj"]
    # Backward Euler's free fall: z after n steps = z0 - g dt^2 n (n + 1) / 2, to rounding.
    z = read_obj(os.path.join(out, "final.obj"))[0][2]
    assert abs(z - (1 - 9.81 * 0.01**2 * 12 * 13 / 2)) < 1e-13, z


def test_a_misspelt_effect_or_key_is_exit_1_naming_it_and_writes_nothing():
    for s, name in [(scene(effects={"gravty": {"g": [0, 0, -1]}}), "effects.gravty"),
                    (scene(solve={"mode": "dynamic", "dt": 0.01, "stpes": 3}), "solve.stpes"),
                    (scene(effects={"pins": {"vertices": [0, 30]}}), "effects.pins.vertices[1]: vertex 30 out of range"),
                    (scene(material={"density": -1, "young": 1, "thickness": 1}), "material.density"),
                    (scene(effects={"bending": {"energy": "tan", "k": -2}}), "effects.bending.k")]:
        p, out = simulate(s)
        assert p.returncode == 1, (name, p.returncode, p.stderr)
        assert name in p.stderr and "scene.json" in p.stderr, (name, p.stderr)
        assert not os.path.exists(os.path.join(out, "final.obj")), name
        assert not os.path.exists(os.path.join(out, "summary.json")), name


def test_an_earlier_out_folder_is_exit_2_unless_overwrite():
    p, out = simulate(scene(), out_exists=True)
    assert p.returncode == 2 and "--overwrite" in p.stderr, (p.returncode, p.stderr)
    p, out = simulate(scene(), "--overwrite", out_exists=True)
    assert p.returncode == 0, p.stderr
    assert json.load(open(os.path.join(out, "summary.json")))["status"] == "ok"


def test_a_run_that_cannot_go_on_says_failed_and_why():
    s = scene(solve={"mode": "static", "max_newton": 1},
              effects={"gravity": {"g": [0, 0, -9.81]}, "stretching": {"model": "stvk"},
                       "bending": {"energy": "tan"}, "pins": {"vertices": [0, 6, 12, 18, 24]}})
    p, out = simulate(s)
    assert p.returncode == 1, p.stderr
    summary = json.load(open(os.path.join(out, "summary.json")))
    assert summary["status"] == "failed" and "Newton did not converge in 1 iterations" in summary["reason"], summary
    assert not os.path.exists(os.path.join(out, "final.obj"))


def test_threads_change_no_output_bit():
    s = scene(mesh={"grid": {"vertices": [9, 9], "size": [1, 1], "center": [0, 0, 0.3], "plane": "xy"}},
              solve={"mode": "dynamic", "dt": 0.01, "steps": 20, "hessian": "exact", "newton_tolerance": 1e-6},
              effects={"gravity": {"g": [0, 0, -9.81]}, "stretching": {"model": "stvk"},
                       "bending": {"energy": "tan"}, "sphere": {"center": [0, 0, 0], "radius": 0.25}})
    # OpenBLAS asked for two threads too: the program holds CHOLMOD's BLAS to one.
    env2 = dict(os.environ, OPENBLAS_NUM_THREADS="2")
    (p1, out1), (p2, out2) = simulate(s, "--threads", "1"), simulate(s, "--threads", "2", env=env2)
    assert p1.returncode == 0 and p2.returncode == 0, (p1.stderr, p2.stderr)
    for name in ["final.obj"] + ["frames/" + f for f in sorted(os.listdir(os.path.join(out1, "frames")))]:
        assert open(os.path.join(out1, name), "rb").read() == open(os.path.join(out2, name), "rb").read(), name
    a, b = (json.load(open(os.path.join(o, "summary.json"))) for o in (out1, out2))
    for key in ("effects", "steps", "newton_iterations", "energy", "status"):
        assert a[key] == b[key], key


def test_the_shipped_scenes_run():
    for name in sorted(os.listdir(SCENES)):
        if name.endswith(".json"):
            s = json.load(open(os.path.join(SCENES, name)))
            for holder in (s["mesh"], s["mesh"].get("rest", {})):  # meshes named relative to the scenes folder
                if "obj" in holder:
                    holder["obj"] = os.path.join(SCENES, holder["obj"])
            if s["solve"]["mode"] == "dynamic":
                s["solve"]["steps"] = 1  # one step of each dynamic scene; static scenes in full
            p, out = simulate(s)
            assert p.returncode == 0, (name, p.stderr)
            assert json.load(open(os.path.join(out, "summary.json")))["status"] == "ok", name


def test_summary_keys_in_the_contracts_order():
    p, out = simulate(scene())
    keys = list(json.load(open(os.path.join(out, "summary.json"))))
    assert keys == ["scene", "status", "effects", "vertices", "steps", "newton_iterations", "time_s", "energy",
                    "bending_share", "solver", "build"], keys


def test_the_solver_block_counts_every_newton_iteration_once():
    s = scene(solve={"mode": "dynamic", "dt": 0.01, "steps": 6, "hessian": "exact"},
              effects={"gravity": {"g": [0, 0, -9.81]}, "stretching": {"model": "stvk"}, "bending": {"energy": "tan"},
                       "pins": {"vertices": [0, 5]}})
    p, out = simulate(s)
    assert p.returncode == 0, p.stderr
    summary = json.load(open(os.path.join(out, "summary.json")))
    solver = summary["solver"]
    assert list(solver) == ["factorizations", "shifted", "newton_per_step", "rungs", "halvings", "limited",
                            "linear_solver"], solver
    assert list(solver["rungs"]) == ["newton", "projected", "shifted", "gradient"], solver
    assert sum(solver["rungs"].values()) == summary["newton_iterations"], solver
    assert solver["factorizations"] >= summary["newton_iterations"] - solver["rungs"]["gradient"], solver
    assert 1 <= solver["newton_per_step"]["median"] <= solver["newton_per_step"]["max"], solver


def test_every_run_writes_its_resolved_scene_and_rest_shape_and_reruns_from_them():
    s = scene(solve={"mode": "dynamic", "dt": 0.01, "steps": 4},
              effects={"gravity": {"g": [0, 0, -9.81]}, "stretching": {"model": "stvk"}, "bending": {"energy": "tan"},
                       "pins": {"vertices": [0, 5]}})
    p, out = simulate(s)
    assert p.returncode == 0, p.stderr
    resolved = json.load(open(os.path.join(out, "scene.json")))
    assert resolved["mesh"]["rest"] == {"obj": "rest.obj"}, resolved
    assert resolved["solve"]["residual_tolerance"] == 1e-8 and resolved["solve"]["hessian"] == "projected", resolved
    assert resolved["effects"]["bending"]["k"] > 0, resolved  # eq. (11)'s value, filled in
    assert len(read_obj(os.path.join(out, "rest.obj"))) == 30
    again = os.path.join(os.path.dirname(out), "again")
    p = subprocess.run([HINGE, "simulate", os.path.join(out, "scene.json"), "--out", again, "--quiet"],
                       capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    assert open(os.path.join(out, "final.obj"), "rb").read() == open(os.path.join(again, "final.obj"), "rb").read()


def test_dump_system_writes_the_named_iterations_and_lists_those_that_never_occurred():
    s = scene(solve={"mode": "dynamic", "dt": 0.01, "steps": 2, "hessian": "exact"},
              effects={"gravity": {"g": [0, 0, -9.81]}, "stretching": {"model": "stvk"}, "bending": {"energy": "tan"},
                       "pins": {"vertices": [0, 5]}})
    p, out = simulate(s, "--dump-system", "1:1,2:1,7:3")
    assert p.returncode == 2, (p.returncode, p.stderr)
    assert "7:3" in p.stderr and "1:1" not in p.stderr, p.stderr
    names = sorted(os.listdir(os.path.join(out, "system")))
    assert names == ["1-1.g", "1-1.mtx", "1-1.obj", "1-1.solved.mtx", "2-1.g", "2-1.mtx", "2-1.obj", "2-1.solved.mtx"]
    free = 3 * (30 - 2)
    gradient = [float(line) for line in open(os.path.join(out, "system", "1-1.g"))]
    assert len(gradient) == free
    for name in ("1-1.mtx", "1-1.solved.mtx"):
        lines = [line for line in open(os.path.join(out, "system", name)) if not line.startswith("%")]
        assert lines[0].split()[:2] == [str(free), str(free)], (name, lines[0])
    assert open(os.path.join(out, "system", "1-1.mtx")).readline().startswith("%%MatrixMarket matrix coordinate real symmetric")
    assert json.load(open(os.path.join(out, "summary.json")))["status"] == "ok"
    for bad in ("1", "1:0", "-1:2", "a:b", "1:2,"):
        p, _ = simulate(s, "--dump-system", bad)
        assert p.returncode == 2 and "--dump-system" in p.stderr, (bad, p.returncode, p.stderr)


def test_a_scene_already_at_equilibrium_is_done_at_once():
    # No force anywhere: the first Newton step is zero (not a failure to find a descent direction).
    s = scene(solve={"mode": "static"}, effects={"stretching": {"model": "stvk"}, "bending": {"energy": "tan"},
                                                 "pins": {"vertices": [0, 6, 12]}})
    p, out = simulate(s)
    assert p.returncode == 0, p.stderr
    assert json.load(open(os.path.join(out, "summary.json")))["newton_iterations"] == 1


def test_a_missing_mesh_file_names_the_scene_and_the_key():
    p, out = simulate(scene(mesh={"obj": "nowhere.obj"}))
    assert p.returncode == 1 and "scene.json: mesh.obj: " in p.stderr and "nowhere.obj" in p.stderr, p.stderr


if __name__ == "__main__":
    sys.exit(run_all(dict(globals())))
