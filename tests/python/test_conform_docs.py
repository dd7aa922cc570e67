"""docs/python-conformance.md run as written, from the repository's root: its first block is
examples/python/numpy_kernel.py; that script with the float32 and the vertex-order sections below it
prints the reports the page shows; the pytest snippet fails with the message the page shows.

The page's ```python blocks are, in order: the kernel (section 1), the float32 lines (section 2), the
vertex-order kernel (section 3), the pytest snippet. Its ```text blocks are what they print, in order;
a line "..." on the page stands for one or more lines left out (the page says where). The comparison
is exact: the text report holds no time and no other varying number, and the library's bits and
NumPy's arithmetic on the same inputs are deterministic (as in test_docs.py)."""

import contextlib
import io
import re
import subprocess
import sys
import types

import pytest

from conftest import ROOT, doc_blocks, shows

PAGE = "docs/python-conformance.md"


def blocks(kind):
    return doc_blocks(PAGE, kind)


@pytest.fixture(scope="module")
def page():
    python, text = blocks("python"), blocks("text")
    assert len(python) == 4 and len(text) == 5, "the page's blocks changed: update this test"
    return python, text


def test_the_kernel_on_the_page_is_examples_python_numpy_kernel_py(page):
    with open(f"{ROOT}/examples/python/numpy_kernel.py") as f:
        assert page[0][0] == f.read()


def test_the_three_examples_print_the_reports_the_page_shows(page):
    (kernel, float32, vbd, _), (a, b, c_without_stencil, c_with_stencil, _) = page
    # Sections 2 and 3 run below the script of section 1, as the page says: one run, four reports.
    result = subprocess.run([sys.executable, "-c", "\n".join([kernel, float32, vbd])], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert result.returncode == 0, result.stderr.decode()
    printed = re.split(r"(?m)^(?=hinge conform: Python function )", result.stdout.decode())
    assert printed[0] == "" and len(printed) == 5
    assert all(report.endswith("\n\n") for report in printed[1:])  # print() adds a newline to str(report)
    reports = [report[:-1] for report in printed[1:]]
    assert reports[0] == a
    assert reports[1] == b
    assert shows(c_without_stencil, reports[2])
    assert shows(c_with_stencil, reports[3])
    # "and then, line for line, the report of section 1"
    first, rest = reports[0].split("\n", 1)
    assert reports[3] == first.replace("function kernel ", "function kernel_vbd ") + "\n" + rest


def test_the_pytest_snippet_fails_on_the_vertex_order_kernel_with_the_message_the_page_shows(page, monkeypatch):
    (kernel, _, vbd, snippet), (*_, message) = page
    namespace = {}
    with contextlib.redirect_stdout(io.StringIO()):  # the scripts print their reports
        exec(kernel + "\n" + vbd, namespace)
    monkeypatch.setitem(sys.modules, "my_solver", types.SimpleNamespace(bending_kernel=namespace["kernel_vbd"]))
    test = {}
    exec(snippet, test)
    with pytest.raises(AssertionError) as failure:
        test["test_bending_kernel_conforms"]()
    assert shows(message, str(failure.value))
