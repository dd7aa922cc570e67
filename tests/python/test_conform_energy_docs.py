"""docs/energy-conformance.md run as written, from the repository's root: its first ```python block is
examples/python/bending_term.py, which prints docs/examples/bending-term-report.txt exactly (the report
holds no time); the page's first ```text block is that report with lines left out ("..." stands for one
or more lines); its second is the diagnosis the same term gets when declared with weight="edge-length"."""

import contextlib
import io
import runpy
import subprocess
import sys

from conftest import ROOT, doc_blocks, shows

PAGE = "docs/energy-conformance.md"


def blocks(kind):
    return doc_blocks(PAGE, kind)


def test_the_example_on_the_page_is_examples_python_bending_term_py():
    with open(f"{ROOT}/examples/python/bending_term.py") as f:
        assert blocks("python")[0] == f.read()


def test_the_example_prints_the_committed_report_and_the_page_shows_it():
    result = subprocess.run([sys.executable, "examples/python/bending_term.py"], cwd=ROOT, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    assert result.returncode == 0, result.stderr.decode()
    with open(f"{ROOT}/docs/examples/bending-term-report.txt") as f:
        committed = f.read()
    assert result.stdout.decode() == committed
    assert shows(blocks("text")[0], committed[:-1])  # print() adds a newline to str(report)


def test_the_undeclared_half_is_diagnosed_as_the_page_says():
    import hinge

    with contextlib.redirect_stdout(io.StringIO()):
        example = runpy.run_path(f"{ROOT}/examples/python/bending_term.py")
    report = hinge.conform_energy(example["bending_term"], energy="shells", k=example["K"], weight="edge-length")
    assert not report.passed
    assert blocks("text")[1] in str(report)
