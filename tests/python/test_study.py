"""hinge.study (docs/study.md, "Your own kernel on the chart"): callables of hinge.conform as outside rows of
the study, measured and timed as the project's rows. Each study here is the least one (fast in double, no
mesh level, short budgets: a second or two): what is asserted is the rows' content, never a time.
"""

import numpy as np
import pytest

import hinge

LABELS = ("x0", "x1", "x2", "x3")
LEAST = {"methods": ["fast"], "scalars": ["double"], "mesh": False, "budget": 0.3}


def fast_kernel(x):
    """The project's fast kernel behind a batched callable (the contract's stencil)."""
    r = hinge.eval(x, method="fast")
    return r.theta, r.grad, r.hess


def swapped_kernel(x):
    """The same kernel for rows in the stencil (x0, x3, x1, x2), its outputs in that variable order."""
    cols = np.array([3 * LABELS.index(v) + c for v in ("x0", "x3", "x1", "x2") for c in range(3)])
    contract = np.empty_like(x)
    contract[:, cols] = x
    r = hinge.eval(contract, method="fast")
    return r.theta, r.grad[:, cols], r.hess[:, cols[:, None], cols[None, :]]


def row(study, method):
    return next(r for r in study["rows"] if r["method"] == method)


def test_a_callable_is_an_outside_row_with_the_errors_of_the_kernel_it_calls(tmp_path):
    s = hinge.study({"mine": fast_kernel}, out=str(tmp_path), **LEAST)
    ours, mine = row(s, "fast"), row(s, "mine")
    assert s["version"] == 2 and "call" in s["timing"]
    assert mine["outside"] is True and ours["outside"] is False and mine["scalar"] == "double"
    # The same doubles as the project's row (hinge.eval is bit for bit the kernel): the same errors.
    assert mine["error_u"] == ours["error_u"]
    assert mine["rounds"] >= 3 and mine["x_fast"]["hess"] > 0
    assert mine["ns_per_hinge"]["theta"] == mine["ns_per_hinge"]["hess"]  # the one call's
    assert (tmp_path / "study.json").exists() and (tmp_path / "study.md").exists()


def test_a_kernel_in_another_stencil_is_mapped_back_as_hinge_conform_maps_it():
    s = hinge.study({"swapped": swapped_kernel}, stencil=("x0", "x3", "x1", "x2"), **LEAST)
    assert row(s, "swapped")["error_u"] == row(s, "fast")["error_u"]


def test_a_finite_difference_kernel_is_measured_far_from_the_oracle():
    def differences(x):
        r = hinge.eval(x, method="fast")
        h = 1e-6  # forward differences of the exact gradient: about sqrt(u) relative, far beyond 1 unit
        hess = np.empty((len(x), 12, 12))
        for j in range(12):
            y = x.copy()
            y[:, j] += h
            hess[:, :, j] = (hinge.eval(y, method="fast").grad - r.grad) / h
        return r.theta, r.grad, hess

    s = hinge.study({"differences": differences}, **LEAST)
    mine = row(s, "differences")
    # h = 1e-6 on unit-sized hinges: errors of order h (1e-6 relative, about 1e10 units of 2^-53).
    assert mine["worst_hess_u"] > 1e6
    assert not mine["on_frontier"]


def test_a_raising_callable_fails_its_row_not_the_study():
    def raising(x):
        raise RuntimeError("not today")

    s = hinge.study({"raising": raising}, **LEAST)
    r = row(s, "raising")
    assert r["failed"] == s["inputs"]["hinges"]  # every hinge missing
    assert "not today" in r["error"]  # and no time, saying why
    assert "hess" not in r["ns_per_hinge"]


@pytest.mark.parametrize("kwargs", [{"candidates": {"x": 1}}, {"methods": []}, {"methods": ["frobnicate"]},
                                    {"scalars": "double"}])
def test_bad_arguments_are_value_errors(kwargs):
    args = dict(LEAST)
    args.update(kwargs)
    candidates = args.pop("candidates", None)
    with pytest.raises(ValueError):
        hinge.study(candidates, **args)
