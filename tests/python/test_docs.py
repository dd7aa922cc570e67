"""The Python examples of the docs, copied from the pages and run verbatim from the repository's root:
docs/python.md's worked example (it asserts its own claim: the NumPy gradient within 8 units of 2^-53 on
well-shaped hinges; and it must print what the page shows) and the README's snippet."""

import re
import subprocess
import sys

from conftest import ROOT


def python_blocks(page):
    with open(f"{ROOT}/{page}") as f:
        return re.findall(r"```python\n(.*?)```", f.read(), re.S)


def run(code):
    result = subprocess.run([sys.executable, "-c", code], cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert result.returncode == 0, result.stderr.decode()
    return result.stdout.decode()


def test_the_worked_example_of_docs_python_md_runs_as_written_and_prints_what_the_page_shows():
    blocks = python_blocks("docs/python.md")
    assert len(blocks) == 1
    with open(f"{ROOT}/docs/python.md") as f:
        shown = re.search(r"Its output here:\n\n```\n(.*?)```", f.read(), re.S).group(1)
    assert run(blocks[0]) == shown  # the library's bits and NumPy's sums are deterministic


def test_the_readme_python_snippet_runs_as_written():
    blocks = python_blocks("README.md")
    assert len(blocks) == 1
    theta, difference = run(blocks[0]).replace("[", " ").replace("]", " ").split()
    assert -3.15 < float(theta) < 3.15 and float(difference) < 1e-15  # the fast kernel: a few units of 2^-53
