"""One bad parameter given to the command, the Python module and a scene gets the same sentence from the
one rule in hinge::core (hinge/core/bending_problem.hpp), each route naming the parameter its own way:
`--k`, `k=`, `effects.bending.k`; a usage error (exit 2), a ValueError, an invalid scene (exit 1)."""

import json
import os
import subprocess

import numpy as np
import pytest

import hinge
from conftest import MESHES

STRIP = os.path.join(MESHES, "strip.obj")
SENTENCE = ": the bending stiffness k must be finite and >= 0, got -1"


def run(*args):
    return subprocess.run([os.environ["HINGE_COMMAND"], *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          text=True)


def scene(tmp_path, bending, material=None):
    path = tmp_path / "scene.json"
    path.write_text(json.dumps({
        "scene": 1, "name": "bad",
        "mesh": {"grid": {"vertices": [3, 3], "size": [1, 1], "center": [0, 0, 0], "plane": "xy"}},
        "material": material or {"density": 1, "young": 1e6, "poisson": 0.3, "thickness": 1e-3},
        "solve": {"mode": "static"},
        "effects": {"bending": bending}}))
    return path


def test_the_same_bad_k_gets_the_same_sentence_from_every_route(tmp_path):
    command = run("hessian", "--mesh", STRIP, "--energy", "tan", "--k", "-1")
    assert command.returncode == 2
    assert "--k" + SENTENCE in command.stderr

    vertices = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.1]], dtype=float)
    faces = np.array([[0, 1, 3], [0, 3, 2]])
    with pytest.raises(ValueError) as python:
        hinge.hessian(vertices, faces, energy="tan", k=-1.0)
    assert str(python.value) == "k=" + SENTENCE

    simulate = run("simulate", str(scene(tmp_path, {"energy": "tan", "k": -1})), "--out", str(tmp_path / "out"))
    assert simulate.returncode == 1
    assert "scene.json: effects.bending.k" + SENTENCE in simulate.stderr


def test_poisson_has_one_range_everywhere(tmp_path):
    """nu in (-1, 0.5]: 0.7 is refused by the command (it was accepted up to 1), a negative nu is accepted
    by a scene (it was refused below 0)."""
    command = run("hessian", "--mesh", STRIP, "--energy", "tan", "--young", "1e6", "--poisson", "0.7",
                  "--thickness", "0.01")
    assert command.returncode == 2
    assert "--poisson: Poisson's ratio nu must be in (-1, 0.5], got 0.7" in command.stderr
    negative = scene(tmp_path, {"energy": "tan"}, {"density": 1, "young": 1e6, "poisson": -0.3, "thickness": 1e-3})
    assert run("simulate", str(negative), "--out", str(tmp_path / "negative")).returncode == 0
    refused = scene(tmp_path, {"energy": "tan"}, {"density": 1, "young": 1e6, "poisson": 0.7, "thickness": 1e-3})
    result = run("simulate", str(refused), "--out", str(tmp_path / "refused"))
    assert result.returncode == 1
    assert "scene.json: material.poisson: Poisson's ratio nu must be in (-1, 0.5], got 0.7" in result.stderr


def test_viscoelastic_is_refused_with_one_sentence(tmp_path):
    reason = ": the viscoelastic energy is library-only: it needs a previous state and a time step"
    command = run("hessian", "--mesh", STRIP, "--energy", "viscoelastic", "--k", "1")
    assert command.returncode == 2 and "--energy" + reason in command.stderr
    with pytest.raises(ValueError) as python:
        hinge.hessian(np.eye(3), np.array([[0, 1, 2]]), energy="viscoelastic", allow_no_hinges=True)
    assert str(python.value) == "energy=" + reason
    simulate = run("simulate", str(scene(tmp_path, {"energy": "viscoelastic", "k": 1})), "--out", str(tmp_path / "o"))
    assert simulate.returncode == 1 and "effects.bending.energy" + reason in simulate.stderr
