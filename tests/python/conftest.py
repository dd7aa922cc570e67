"""Fixtures of the Python module's tests (ctest label python): the hinge command they compare with
(HINGE_COMMAND, set by tests/CMakeLists.txt), and the committed inputs. The module itself is imported
from PYTHONPATH (<build>/python)."""

import glob
import json
import os
import re
import subprocess

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
HINGES = sorted(glob.glob(os.path.join(ROOT, "conformance", "hinges", "*.jsonl")))
MESHES = os.path.join(ROOT, "conformance", "meshes")


@pytest.fixture(scope="session")
def command():
    """Runs the hinge command; returns its standard output (bytes)."""
    path = os.environ["HINGE_COMMAND"]

    def run(*args, stdin=None):
        return subprocess.run([path, *args], input=stdin, stdout=subprocess.PIPE, check=True).stdout

    return run


@pytest.fixture(scope="session")
def conformance_file(tmp_path_factory):
    """Every committed conformance hinge (306, nine categories) in one JSON Lines file."""
    path = tmp_path_factory.mktemp("inputs") / "hinges.jsonl"
    with open(path, "wb") as out:
        for name in HINGES:
            with open(name, "rb") as f:
                out.write(f.read())
    return str(path)


def read_x(path):
    with open(path) as f:
        return np.array([json.loads(line)["x"] for line in f if line.strip()])


def read_results(text):
    """The command's output lines as (theta, grad, hess, error) per line."""
    return [json.loads(line) for line in text.decode().splitlines()]


def doc_blocks(page, kind):
    """The ```kind fenced blocks of a docs page (path from the repository's root), in order."""
    with open(f"{ROOT}/{page}") as f:
        return re.findall(rf"```{kind}\n(.*?)```", f.read(), re.S)


def shows(shown, printed):
    """Whether `printed` is `shown`, each line "..." of `shown` standing for one or more lines."""
    pattern = "".join(r"(?:.*\n)+" if line == "...\n" else re.escape(line) for line in shown.splitlines(True))
    return re.fullmatch(pattern, printed) is not None
