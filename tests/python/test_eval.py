"""hinge.eval: bit for bit `hinge eval` with the same method and scalar type; bad arguments raise
ValueError; an invalid hinge gets NaN rows and the command's message."""

import numpy as np
import pytest

import hinge
from conftest import read_results, read_x

CASES = [("fast", "double"), ("reference", "double"), ("fast", "long-double"), ("reference", "float"),
         ("autodiff", "double"), ("symbolic", "dd"), ("fast", "mpfr:128")]


def assert_same_as_command(result, lines):
    assert len(result) == len(lines)
    for i, line in enumerate(lines):
        if "error" in line:
            assert result.error[i] == line["error"]
            assert np.isnan(result.theta[i]) and np.isnan(result.grad[i]).all() and np.isnan(result.hess[i]).all()
            continue
        assert result.error[i] is None
        # == on doubles parsed from shortest round-trip text: bit for bit (and +0 / -0 compared by sign).
        assert result.theta[i] == line["theta"] and np.signbit(result.theta[i]) == np.signbit(line["theta"])
        np.testing.assert_array_equal(result.grad[i], line["grad"])
        np.testing.assert_array_equal(result.hess[i].ravel(), line["hess"])
        assert (np.signbit(result.hess[i].ravel()) == np.signbit(line["hess"])).all()


@pytest.mark.parametrize("method,scalar", CASES)
def test_eval_is_bit_for_bit_the_command(command, conformance_file, method, scalar):
    lines = read_results(command("eval", "--method", method, "--scalar", scalar, "--input", conformance_file))
    assert_same_as_command(hinge.eval(read_x(conformance_file), method=method, scalar=scalar), lines)


def test_faithful_is_bit_for_bit_the_command(command, conformance_file):
    lines = read_results(command("eval", "--method", "fast", "--faithful", "--input", conformance_file))
    assert_same_as_command(hinge.eval(read_x(conformance_file), method="fast", faithful=True), lines)


@pytest.mark.parametrize("kwargs", [{"method": "reference"}, {"scalar": "long-double"}])
def test_faithful_with_another_method_or_scalar_raises_value_error(kwargs):
    with pytest.raises(ValueError, match="faithful"):
        hinge.eval(np.zeros((1, 12)), faithful=True, **kwargs)


def test_a_single_hinge_and_any_float_dtype_and_layout_are_accepted(conformance_file):
    x = read_x(conformance_file)[:8]
    expected = hinge.eval(x)
    assert hinge.eval(x[0]).theta.shape == (1,)
    assert hinge.eval(x[0]).theta[0] == expected.theta[0]
    fortran = np.asfortranarray(x)
    np.testing.assert_array_equal(hinge.eval(fortran).hess, expected.hess)
    np.testing.assert_array_equal(hinge.eval(x[::-1]).grad, expected.grad[::-1])  # a negative stride
    small = np.array([[0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]], dtype=np.int32)
    assert hinge.eval(small).error == [None]
    assert hinge.eval(x.tolist()).theta.tolist() == expected.theta.tolist()


def test_degenerate_and_non_finite_hinges_get_nan_rows_and_the_reason():
    x = np.zeros((3, 12))
    x[1] = [0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
    x[2] = x[1]
    x[2][5] = np.inf
    r = hinge.eval(x)
    assert r.error[1] is None and r.error[0] and r.error[2]
    assert "zero length" in r.error[0] and "finite" in r.error[2]
    assert np.isnan(r.theta[[0, 2]]).all() and not np.isnan(r.theta[1])


@pytest.mark.parametrize("x,message", [
    (np.zeros((3, 11)), "shape"), (np.zeros((2, 12, 1)), "shape"), (np.zeros(13), "shape"),
    (np.array([["a"] * 12]), "float64"), ("hinge", "float64"),
])
def test_bad_arrays_raise_value_error_naming_the_problem(x, message):
    with pytest.raises(ValueError, match=message):
        hinge.eval(x)


@pytest.mark.parametrize("kwargs,message", [
    ({"method": "newton"}, "unknown method 'newton'"), ({"scalar": "quad"}, "quad"), ({"scalar": "mpfr:1"}, "mpfr"),
])
def test_unknown_methods_and_scalars_raise_value_error(kwargs, message):
    with pytest.raises(ValueError, match=message):
        hinge.eval(np.zeros((1, 12)), **kwargs)


def test_an_empty_array_gives_empty_results():
    r = hinge.eval(np.zeros((0, 12)))
    assert r.theta.shape == (0,) and r.grad.shape == (0, 12) and r.hess.shape == (0, 12, 12) and r.error == []


def test_threads_with_different_mpfr_precisions_do_not_disturb_each_other(conformance_file):
    # Boost's MPFR default precision is one for the whole process: the module serializes mpfr evaluations.
    import threading
    x = read_x(conformance_file)[:60]
    alone = {s: hinge.eval(x, method="reference", scalar=s).hess for s in ("mpfr:24", "mpfr:2000")}
    differ = []

    def work(scalar):
        for _ in range(3):
            if not np.array_equal(hinge.eval(x, method="reference", scalar=scalar).hess, alone[scalar], equal_nan=True):
                differ.append(scalar)

    threads = [threading.Thread(target=work, args=(s,)) for s in ("mpfr:24", "mpfr:2000") * 2]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert differ == []
