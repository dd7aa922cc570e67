"""hinge.conform and hinge.testing.assert_conforms (docs/python-conformance.md): candidates built as
simulators' kernels go wrong, each graded and, where it breaks a convention, diagnosed.

The candidates start from the certified values (hinge.oracle) and apply one convention slip each, so that
what the kit must say is known exactly: a certified value in another convention fails by far more than
any tolerance, and the diagnosis must name exactly that convention. The candidate's rows are in its own
stencil and dtype, as conform hands them over.
"""

import json
import math
import re

import numpy as np
import pytest

import hinge
from hinge.testing import assert_conforms

LABELS = ("x0", "x1", "x2", "x3")


def columns(stencil):
    """The contract's column of the candidate's variable i."""
    return np.array([3 * LABELS.index(label) + c for label in stencil for c in range(3)])


def certified(stencil=LABELS):
    """A kernel returning the certified values, in its own stencil order (its input rows in that order)."""
    cols = columns(stencil)

    def kernel(X):
        x = np.empty_like(X, dtype=np.float64)
        x[:, cols] = X  # back to the contract's order
        r = hinge.oracle(x)
        grad = r.grad[:, cols]
        hess = r.hess[:, cols[:, None], cols[None, :]]
        return {"theta": r.theta, "grad": grad, "hess": hess}

    return kernel


def transformed(f, stencil=LABELS):
    base = certified(stencil)

    def kernel(X):
        out = base(X)
        return f(out["theta"].copy(), out["grad"].copy(), out["hess"].copy())

    return kernel


def named(report, pattern):
    return [s for s in report.diagnosis if re.search(pattern, s)]


# --- what passes


def test_a_kernel_returning_the_certified_values_is_correctly_rounded():
    report = hinge.conform(certified())
    assert report.passed and report.tier == "correctly-rounded" and report.diagnosis == []


def test_the_certified_values_in_another_declared_stencil_are_correctly_rounded():
    stencil = ("x0", "x3", "x1", "x2")
    report = hinge.conform(certified(stencil), stencil=stencil)
    assert report.passed and report.tier == "correctly-rounded"
    worst = report.categories["well-shaped"]["worst_case"]
    x, xc = np.array(worst["x"]), np.array(worst["x_candidate"])
    assert (xc == x[columns(stencil)]).all()  # x_candidate is the candidate's order of x


def test_one_hinge_at_a_time_grades_the_same():
    calls = []

    def kernel(x):
        calls.append(x.shape)
        out = certified()(x[None])
        return out["theta"][0], out["grad"][0], out["hess"][0]

    report = hinge.conform(kernel, batch=False)
    assert report.tier == "correctly-rounded" and set(calls) == {(12,)}


def test_a_foreign_array_type_with_only_dunder_array_is_accepted():
    class Foreign:  # a GPU framework's array, as far as NumPy sees it
        def __init__(self, a):
            self._a = a

        def __array__(self, dtype=None, copy=None):
            return np.asarray(self._a, dtype=dtype)

    def kernel(X):
        out = certified()(X)
        return {k: Foreign(v) for k, v in out.items()}

    assert hinge.conform(kernel).tier == "correctly-rounded"


def test_theta_and_gradient_only_are_graded_and_the_hessian_is_reported_not_checked():
    def kernel(X):
        out = certified()(X)
        return out["theta"], out["grad"]

    report = hinge.conform(kernel, outputs=("theta", "grad"))
    assert report.passed and report.tier == "correctly-rounded"
    assert report.categories["well-shaped"]["hess"] == {"median": None, "max": None}
    assert "not checked" in str(report) and json.loads(report.to_json())["given"] == ["theta", "grad"]


def test_a_perfect_float32_kernel_passes_in_float32():
    def kernel(X):
        assert X.dtype == np.float32
        out = certified()(X.astype(np.float64))
        return {k: v.astype(np.float32) for k, v in out.items()}  # the certified double rounded to float

    report = hinge.conform(kernel, dtype="float32")
    assert report.passed, str(report)
    assert "2^-24" in str(report)


def test_a_float64_kernel_in_a_float32_run_is_accepted_and_rounded():
    report = hinge.conform(certified(), dtype="float32")
    assert report.passed, str(report)


# --- what fails, and why


def test_an_undeclared_stencil_fails_and_the_diagnosis_names_the_order_to_declare():
    report = hinge.conform(certified(("x0", "x3", "x1", "x2")))
    assert not report.passed and report.tier == "fail"
    assert named(report, r"the vertex order \(x0, x3, x1, x2\).*stencil=\(\"x0\", \"x3\", \"x1\", \"x2\"\)")


def test_a_negated_angle_fails_and_the_diagnosis_names_it_once_with_its_equivalent_stencil():
    report = hinge.conform(transformed(lambda t, g, h: (-t, -g, -h)))
    assert report.tier == "fail"
    found = named(report, r"theta negated \(the same as the stencil \(x0, x2, x1, x3\)\)")
    assert len(found) == 1 and len(report.diagnosis) == 1


def test_degrees_fail_and_the_diagnosis_names_them():
    c = 180 / math.pi
    report = hinge.conform(transformed(lambda t, g, h: (c * t, c * g, c * h)))
    assert report.tier == "fail" and named(report, r"theta in degrees\.")


def test_theta_alone_in_degrees_is_told_apart():
    report = hinge.conform(transformed(lambda t, g, h: (t * 180 / math.pi, g, h)))
    assert named(report, r"theta in degrees \(its derivatives in radians\)")


def test_a_hessian_with_one_triangle_filled_fails_and_the_diagnosis_names_the_triangle():
    upper = np.triu(np.ones((12, 12)))
    report = hinge.conform(transformed(lambda t, g, h: (t, g, h * upper)))
    assert report.tier == "fail" and named(report, r"only its upper matrix triangle right")
    lower = np.tril(np.ones((12, 12)))
    report = hinge.conform(transformed(lambda t, g, h: (t, g, h * lower)))
    assert named(report, r"only its lower matrix triangle right")


def test_the_triangle_is_judged_in_the_candidates_own_order():
    stencil = ("x3", "x2", "x0", "x1")
    upper = np.triu(np.ones((12, 12)))
    report = hinge.conform(transformed(lambda t, g, h: (t, g, h * upper), stencil), stencil=stencil)
    assert named(report, r"only its upper matrix triangle right")


def test_the_unsigned_angle_is_diagnosed():
    def f(t, g, h):
        s = np.where(t < 0, -1.0, 1.0)
        return np.abs(t), g * s[:, None], h * s[:, None, None]

    report = hinge.conform(transformed(f))
    assert named(report, r"the unsigned angle \|theta\|")


def test_pi_minus_the_unsigned_angle_is_diagnosed():
    def f(t, g, h):
        s = np.where(t < 0, -1.0, 1.0)
        return math.pi - np.abs(t), -g * s[:, None], -h * s[:, None, None]

    assert named(hinge.conform(transformed(f)), r"pi - \|theta\|")


def test_an_angle_in_zero_to_two_pi_is_diagnosed():
    report = hinge.conform(transformed(lambda t, g, h: (np.where(t < 0, t + 2 * math.pi, t), g, h)))
    assert named(report, r"theta in \[0, 2 pi\)")
    assert report.categories["well-shaped"]["tier"] == "fail"


def test_minus_pi_on_the_branch_cut_is_diagnosed_in_the_category_that_holds_the_cut():
    report = hinge.conform(transformed(lambda t, g, h: (np.where(t == math.pi, -math.pi, t), g, h)))
    failing = [c for c, v in report.categories.items() if v["tier"] == "fail"]
    assert failing and all(named(report, rf"{c}.*-pi on the branch cut") for c in failing)


def test_a_negated_gradient_is_diagnosed_as_a_force():
    assert named(hinge.conform(transformed(lambda t, g, h: (t, -g, h))), r"the gradient negated \(a force\)")


def test_a_negated_gradient_and_hessian_are_diagnosed_as_a_force_and_its_jacobian():
    report = hinge.conform(transformed(lambda t, g, h: (t, -g, -h)))
    assert named(report, r"the gradient and Hessian negated \(a force and its Jacobian\)")
    assert not named(report, r"the gradient negated \(a force\)\.")


def test_coordinate_major_variables_are_diagnosed():
    order = np.array([3 * v + c for c in range(3) for v in range(4)])  # x0.x, x1.x, x2.x, x3.x, x0.y, ...

    report = hinge.conform(transformed(lambda t, g, h: (t, g[:, order], h[:, order[:, None], order[None, :]])))
    assert named(report, r"coordinate-major")


def test_every_output_off_by_a_relative_1e_9_is_approximate_not_fail_and_gets_no_diagnosis():
    f = 1 + 1e-9
    report = hinge.conform(transformed(lambda t, g, h: (t * f, g * f, h * f)))
    assert not report.passed
    assert report.categories["well-shaped"]["tier"] == "approximate"
    assert report.diagnosis == []


def test_a_kernel_raising_on_some_hinges_has_those_not_evaluated_and_the_others_graded():
    base = certified()
    calls = {"batch": 0}

    def kernel(X):
        if len(X) > 1:
            calls["batch"] += 1
        if (np.abs(X) > 1e3).any():
            raise FloatingPointError("overflow in my kernel")
        return base(X)

    report = hinge.conform(kernel)
    assert calls["batch"] == 1  # the batch raised once, then every hinge alone
    assert report.categories["well-shaped"]["tier"] == "correctly-rounded"
    raised = report.categories["offsets"]
    assert raised["missing"] > 0 and raised["tier"] == "fail"
    assert "fn raised FloatingPointError: overflow in my kernel" in str(report)


def test_a_nan_row_is_not_evaluated_and_an_infinity_is_nonfinite():
    base = certified()

    def kernel(X):
        out = base(X)
        out["theta"][0] = np.nan
        out["grad"][1, 3] = np.inf
        return out

    report = hinge.conform(kernel)
    first = next(iter(report.categories.values()))
    assert first["missing"] == 1 and first["nonfinite"] == 1


def test_assert_conforms_raises_with_the_report_text_and_returns_the_report_when_it_passes():
    assert assert_conforms(certified(), tier="correctly-rounded").passed
    with pytest.raises(AssertionError) as failure:
        assert_conforms(transformed(lambda t, g, h: (-t, -g, -h)))
    assert "theta negated" in str(failure.value) and "hinge conform: Python function" in str(failure.value)


def test_the_html_report_is_one_self_contained_file(tmp_path):
    report = hinge.conform(transformed(lambda t, g, h: (-t, -g, -h)))
    path = tmp_path / "report.html"
    report.to_html(path)
    assert [p.name for p in tmp_path.iterdir()] == ["report.html"]
    page = path.read_text()
    assert "<svg" in page and "theta negated" in page
    for link in re.findall(r"""(?:src|href)\s*=\s*["']?([^"' >]*)|url\(\s*["']?([^"')]*)|@import\s+["']?([^"';]*)""", page):
        target = next(t for t in link if t) if any(link) else ""
        assert target.startswith("#") or target.startswith("data:"), target


def test_the_json_report_is_the_commands_with_diagnosis_and_worst_case_detail():
    report = hinge.conform(transformed(lambda t, g, h: (-t, -g, -h)))
    data = json.loads(report.to_json())
    assert data["diagnosis"] == report.diagnosis and data["pass"] is False
    detail = data["categories"][0]["worst_case_detail"]
    assert set(detail) >= {"id", "x", "x_candidate", "expected", "got", "output", "entry"}


# --- bad input


@pytest.mark.parametrize(
    "options, message",
    [
        ({"stencil": ("x0", "x1", "x2", "x4")}, r"stencil=: unknown label 'x4'"),
        ({"stencil": ("x0", "x1", "x1", "x3")}, r"stencil= must be a permutation"),
        ({"stencil": "x0x1x2x3"}, r"stencil= must be a sequence"),
        ({"dtype": "float16"}, r"dtype= must be 'float64' or 'float32'"),
        ({"depth": "shallow"}, r"depth= must be one of"),
        ({"outputs": ("grad",)}, r"outputs= must be"),
        ({"outputs": ("theta", "hessian")}, r"outputs=: unknown output 'hessian'"),
    ],
)
def test_a_bad_argument_is_a_value_error_naming_it(options, message):
    with pytest.raises(ValueError, match=message):
        hinge.conform(certified(), **options)


def test_an_unknown_tier_is_a_value_error():
    with pytest.raises(ValueError, match=r"tier= must be one of"):
        assert_conforms(certified(), tier="perfect")


@pytest.mark.parametrize(
    "bad, message",
    [
        (lambda out: {**out, "grad": out["grad"][:, :9]}, r"grad of shape \(\d+, 9\) for n = \d+ hinges; expected \(n, 12\)"),
        (lambda out: {**out, "theta": out["theta"][:-1]}, r"theta of shape"),
        (lambda out: {**out, "hess": out["hess"].astype(np.complex128)}, r"hess of dtype complex128"),
        (lambda out: {"theta": out["theta"], "grad": out["grad"]}, r"dict without hess"),
        (lambda out: (out["theta"], out["grad"]), r"returned 2 values; expected 3"),
        (lambda out: "nonsense", r"must return a dict"),
    ],
)
def test_a_wrong_output_is_a_value_error_naming_the_output_and_the_shape_expected(bad, message):
    base = certified()
    with pytest.raises(ValueError, match=message):
        hinge.conform(lambda X: bad(base(X)))


def test_theta_alone_negated_is_told_apart_from_a_negated_convention():
    report = hinge.conform(transformed(lambda t, g, h: (-t, g, h)))
    assert named(report, r"theta negated, its derivatives not") and not named(report, r"the same as the stencil")


def test_a_batch_that_raises_while_every_hinge_passes_alone_is_noted():
    base = certified()

    def kernel(X):
        if len(X) > 100:
            raise RuntimeError("out of GPU memory")
        return base(X)

    report = hinge.conform(kernel)
    assert report.passed  # every hinge alone is right
    assert len(report.notes) == 1 and "out of GPU memory" in report.notes[0] and "no hinge raised alone" in report.notes[0]
    assert "note: the batch call" in str(report)


def test_a_list_is_accepted_as_the_single_output():
    base = certified()
    report = hinge.conform(lambda X: list(base(X)["theta"]), outputs=("theta",))
    assert report.tier == "correctly-rounded"


def test_a_missing_case_makes_its_groups_worst_error_infinite_and_a_group_not_given_none():
    base = certified()

    def kernel(X):
        out = base(X)
        out["theta"][0] = np.nan
        return out["theta"], out["grad"]

    first = next(iter(hinge.conform(kernel, outputs=("theta", "grad")).categories.values()))
    assert first["theta"]["max"] == math.inf and first["grad"]["max"] == math.inf and first["hess"]["max"] is None


def test_a_float_overflow_in_a_float32_run_is_non_finite():
    base = certified()

    def kernel(X):
        out = base(X.astype(np.float64))
        out["theta"][0] = 1e300  # finite in double, infinite in float
        return out

    first = next(iter(hinge.conform(kernel, dtype="float32").categories.values()))
    assert first["nonfinite"] == 1 and first["missing"] == 0


def test_the_negated_angle_of_a_real_kernel_is_named_in_every_category_including_the_folded_ones():
    # A kernel in the order (x0, x2, x1, x3): its theta is the contract's negated, but +pi stays +pi on the
    # branch cut (any order gives +pi there), so "theta negated" must keep +pi at the cut.
    def reversed_edge(X):
        out = certified(("x0", "x2", "x1", "x3"))(X)
        return out["theta"], out["grad"], out["hess"]

    report = hinge.conform(reversed_edge, depth="deep")
    found = named(report, r"theta negated \(the same as the stencil \(x0, x2, x1, x3\)\)")
    failing = [c for c, v in report.categories.items() if v["tier"] == "fail"]
    assert len(found) == 1 and all(c in found[0] for c in failing), report.diagnosis


def test_a_theta_only_kernel_with_zero_on_the_cut_gets_no_vertex_order_advice():
    def zero_on_cut(X):
        t = certified()(X)["theta"]
        return np.where(t == math.pi, 0.0, t)

    report = hinge.conform(zero_on_cut, outputs=("theta",), depth="deep")
    assert not named(report, r"vertex order"), report.diagnosis


def test_with_theta_alone_a_variant_differing_only_in_the_derivatives_is_not_named_again():
    report = hinge.conform(lambda X: -certified()(X)["theta"], outputs=("theta",))
    assert not named(report, r"its derivatives not") and named(report, r"theta negated")


@pytest.mark.parametrize(
    "options, message",
    [
        ({"dtype": None}, r"dtype= must be"),
        ({"stencil": {"x0": 0, "x1": 1, "x2": 2, "x3": 3}}, r"stencil= must be a sequence"),
        ({"depth": np.array(["quick"])}, r"depth= must be one of"),
    ],
)
def test_more_bad_arguments_are_value_errors(options, message):
    with pytest.raises(ValueError, match=message):
        hinge.conform(certified(), **options)
