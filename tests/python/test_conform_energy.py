"""hinge.conform_energy (docs/energy-conformance.md): bending terms as simulators write them, right and with the
mistakes their trackers report, each graded and, where wrong, diagnosed."""

import html
import json
import re
import sys
import types

import numpy as np
import pytest

import hinge
from bending_terms import (
    bridson_term,
    contract_weight,
    edge_length,
    quadratic_term,
    shells_term,
    tan_term,
    willmore_term,
)


def sentence(report):
    return " ".join(report.diagnosis)


def test_a_correct_tan_term_passes_with_its_consistency_checks():
    r = hinge.conform_energy(tan_term())
    assert r.passed, str(r)
    assert r.tier in ("correctly-rounded", "faithful", "4u", "policy")
    assert r.diagnosis == []
    assert r.checks and all(c["pass"] for c in r.checks)
    assert r.settings == {"energy": "tan", "weight": "contract", "k": "1", "hessian": "exact", "blocks": "full"}


def test_every_rest_kind_is_a_category_and_the_left_out_pairs_are_counted():
    r = hinge.conform_energy(tan_term())
    kinds = {c.split("/")[1] for c in r.categories}
    assert kinds == {"flat", "obtuse", "negative", "near-cut", "at-rest", "rest-angle"}
    assert any("pairs left out, not graded" in n and "|theta - theta_bar| > pi" in n for n in r.notes)


def test_a_weight_missing_the_3_fails_and_is_named():
    r = hinge.conform_energy(tan_term(weight=lambda R: contract_weight(R) / 3))
    assert not r.passed
    assert "1/3 times the declared one" in sentence(r) and "its 3 is missing" in sentence(r)


def test_an_extra_factor_of_the_rest_edge_length_fails_and_is_named():
    r = hinge.conform_energy(tan_term(weight=lambda R: contract_weight(R) * edge_length(R)))
    assert not r.passed
    assert "extra factor |e_bar|" in sentence(r)


def test_a_weight_not_divided_by_the_rest_edge_length_is_named():
    r = hinge.conform_energy(tan_term(weight=lambda R: contract_weight(R) / edge_length(R)))
    assert not r.passed
    assert "misses a factor |e_bar|" in sentence(r)


def test_a_gauss_newton_hessian_declared_exact_fails_and_passes_when_declared_so():
    wrong = hinge.conform_energy(tan_term(gauss_newton=True))
    assert not wrong.passed
    assert "Gauss-Newton Hessian" in sentence(wrong) and "where the exact one was declared" in sentence(wrong)
    assert not wrong.categories["well-shaped/flat"]["hess"]["max"] <= 1e6
    right = hinge.conform_energy(tan_term(gauss_newton=True), hessian="gauss-newton")
    assert right.passed, str(right)
    assert all(c["check"] != "Hessian against differences of the gradient" for c in right.checks)


def projected(term):
    """The term with each hinge's Hessian projected: its negative eigenvalues set to zero (NumPy's eigh)."""

    def projected_term(X, R):
        psi, g, H = term(X, R)
        w, V = np.linalg.eigh(H)
        return psi, g, np.einsum("nij,nj,nkj->nik", V, np.maximum(w, 0), V)

    return projected_term


def mixed_precision(term):
    """A float32 kernel that computes in double: float32 arrays in, float32 arrays out."""

    def kernel(X, R):
        assert X.dtype == np.float32 and R.dtype == np.float32
        return tuple(np.asarray(a, dtype=np.float32) for a in term(X.astype(np.float64), R.astype(np.float64)))

    return kernel


@pytest.mark.parametrize("energy, term", [("tan", tan_term), ("shells", shells_term), ("quadratic", quadratic_term)])
def test_float32_terms_pass_on_the_float32_pairs(energy, term):
    r = hinge.conform_energy(mixed_precision(term()), energy=energy, dtype="float32")
    assert r.passed, str(r)
    assert "2^-24" in str(r)


def test_in_float32_the_missing_3_and_the_rest_angle_off_by_2pi_are_named_alone():
    third = hinge.conform_energy(mixed_precision(tan_term(weight=lambda R: contract_weight(R) / 3)), dtype="float32")
    assert not third.passed and len(third.diagnosis) == 1 and "1/3 times the declared one" in third.diagnosis[0]
    shifted = shells_term(rest_angle=lambda tb: np.where(tb < 0, tb + 2 * np.pi, tb))
    r = hinge.conform_energy(mixed_precision(shifted), energy="shells", dtype="float32")
    assert not r.passed and "[0, 2 pi)" in sentence(r)


def test_a_float32_weight_from_long_edges_fails_where_the_edges_are_long():
    # The weight computed in float32 from a needle's long edges cancels (its cross product loses every digit).
    def float32_weight(R):
        V = R.reshape(-1, 4, 3)  # float32 arithmetic throughout
        n0 = np.cross(V[:, 1] - V[:, 0], V[:, 2] - V[:, 0])
        n3 = np.cross(V[:, 2] - V[:, 3], V[:, 1] - V[:, 3])
        e = V[:, 2] - V[:, 1]
        return 6 * np.einsum("ij,ij->i", e, e) / (np.linalg.norm(n0, axis=1) + np.linalg.norm(n3, axis=1))

    term = tan_term(weight=float32_weight)
    r = hinge.conform_energy(lambda X, R: tuple(np.asarray(a, np.float32) for a in term(X, R)), dtype="float32")
    assert not r.passed
    assert r.categories["needles/at-rest"]["tier"] in ("fail", "approximate")


def test_the_deep_depth_adds_the_hard_families_and_a_correct_term_still_passes():
    quick = hinge.conform_energy(tan_term())
    deep = hinge.conform_energy(tan_term(), depth="deep")
    assert deep.passed, str(deep)
    assert json.loads(deep.to_json())["depth"] == "deep"
    count = lambda r: sum(c["cases"] for c in r.categories.values())  # noqa: E731
    assert count(deep) >= count(quick) + 700
    assert {"folded/flat", "combined/near-cut"} <= set(deep.categories)


def test_a_projected_hessian_passes_against_the_256_bit_reference_at_best_at_tier_policy():
    r = hinge.conform_energy(projected(tan_term()), hessian="projected")
    assert r.passed, str(r)
    assert r.tier == "policy"
    assert all(c["tier"] == "policy" for c in r.categories.values())
    assert any("not certified: 256-bit reference" in n for n in r.notes)


def test_an_exact_hessian_declared_projected_is_named():
    r = hinge.conform_energy(tan_term(), hessian="projected")
    assert not r.passed
    assert "the exact Hessian given where the projected one was declared" in sentence(r)


def test_an_exact_hessian_declared_gauss_newton_is_named():
    r = hinge.conform_energy(tan_term(), hessian="gauss-newton")
    assert not r.passed
    assert "the exact Hessian given where the Gauss-Newton one was declared" in sentence(r)


def test_shells_with_rest_angles_in_0_2pi_fails_and_the_diagnosis_names_the_2pi():
    r = hinge.conform_energy(
        shells_term(rest_angle=lambda tb: np.where(tb < 0, tb + 2 * np.pi, tb)), energy="shells"
    )
    assert not r.passed
    assert "[0, 2 pi)" in sentence(r)
    assert r.categories["well-shaped/flat"]["tier"] != "fail"  # theta_bar = 0 is in both ranges


@pytest.mark.parametrize(
    "rest_angle, words",
    [
        (lambda tb: 0 * tb, "rest angle ignored"),
        (lambda tb: -tb, "rest angle negated"),
        (lambda tb: np.degrees(tb), "rest angle in degrees"),
    ],
)
def test_a_wrong_rest_angle_is_named(rest_angle, words):
    r = hinge.conform_energy(shells_term(rest_angle=rest_angle), energy="shells")
    assert not r.passed
    assert words in sentence(r)


@pytest.mark.parametrize("energy, term", [("shells", shells_term), ("willmore", willmore_term), ("bridson", bridson_term)])
def test_a_correct_shells_willmore_and_bridson_term_pass(energy, term):
    r = hinge.conform_energy(term(), energy=energy)
    assert r.passed, str(r)


def test_a_term_in_its_own_vertex_order_passes_when_it_declares_it():
    order = [0, 3, 1, 2]  # the candidate's vertex j is the contract's x_order[j]
    columns = np.array([3 * order[j] + c for j in range(4) for c in range(3)])
    inverse = np.argsort(columns)
    contract = tan_term()

    def vbd_term(X, R):  # receives and returns its own order
        psi, g, H = contract(X[:, inverse], R[:, inverse])
        return psi, g[:, columns], H[:, columns[:, None], columns[None, :]]

    assert hinge.conform_energy(vbd_term, stencil=("x0", "x3", "x1", "x2")).passed
    assert not hinge.conform_energy(vbd_term).passed


def test_diagonal_blocks_grade_only_what_vertex_block_descent_computes():
    contract = tan_term()

    def diagonal_only(X, R):
        psi, g, H = contract(X, R)
        blocks = np.zeros_like(H)
        for v in range(4):
            blocks[:, 3 * v : 3 * v + 3, 3 * v : 3 * v + 3] = H[:, 3 * v : 3 * v + 3, 3 * v : 3 * v + 3]
        return psi, g, blocks

    r = hinge.conform_energy(diagonal_only, blocks="diagonal")
    assert r.passed, str(r)
    assert any("diagonal blocks were graded" in n for n in r.notes)
    assert not hinge.conform_energy(diagonal_only).passed


def test_named_and_callable_weights():
    term = tan_term(weight=edge_length)
    assert hinge.conform_energy(term, weight="edge-length").passed
    assert hinge.conform_energy(term, weight=edge_length).passed
    r = hinge.conform_energy(term)  # graded against the contract's weight
    assert not r.passed


def test_k_scales_the_term():
    assert hinge.conform_energy(tan_term(k=2.5), k=2.5).passed
    r = hinge.conform_energy(tan_term(k=2.5))
    assert not r.passed and "5/2 times the declared one" in sentence(r)


def test_a_custom_term_whose_gradient_is_1_percent_off_its_energy_fails_the_consistency_checks():
    contract = tan_term()

    def off(X, R):
        psi, g, H = contract(X, R)
        return psi, 1.01 * g, H

    good = hinge.conform_energy(contract, energy="custom")
    assert good.passed and good.tier is None and good.categories == {}
    bad = hinge.conform_energy(off, energy="custom")
    assert not bad.passed
    failed = {c["check"] for c in bad.checks if not c["pass"]}
    assert "gradient against differences of the energy" in failed


def test_outputs_may_leave_out_the_hessian():
    contract = tan_term()
    r = hinge.conform_energy(lambda X, R: contract(X, R)[:2], outputs=("energy", "grad"))
    assert r.passed, str(r)
    assert all(v["hess"] == {"median": None, "max": None} for v in r.categories.values())


def test_a_nan_is_missing_and_a_raising_batch_is_retried():
    contract = tan_term()

    def nan_on_flat(X, R):
        psi, g, H = contract(X, R)
        psi = psi.copy()
        psi[0] = np.nan
        return psi, g, H

    r = hinge.conform_energy(nan_on_flat)
    assert not r.passed and r.categories["well-shaped/flat"]["missing"] >= 1


def test_the_json_report_carries_settings_and_checks():
    j = json.loads(hinge.conform_energy(tan_term()).to_json())
    assert j["given"] == ["energy", "grad", "hess"]
    assert j["settings"]["energy"] == "tan"
    assert {c["check"] for c in j["consistency"]} >= {"net force", "net torque", "Hessian symmetry"}
    assert "rest" in j["categories"][0]["worst_case_detail"]


@pytest.mark.parametrize(
    "options",
    [
        {"energy": "quadratic", "hessian": "gauss-newton"},
        {"energy": "quadratic", "weight": "unit"},
        {"hessian": "newton"},
        {"dtype": "float32", "depth": "deep"},
        {"dtype": "float32", "hessian": "projected"},
        {"depth": "deeper"},
        {"energy": "viscoelastic"},
        {"weight": "cotangent"},
        {"weight": 3.0},
        {"weight": lambda R: -np.ones(len(R))},
        {"k": 0.0},
        {"k": float("nan")},
        {"blocks": "upper"},
        {"outputs": ("theta",)},
    ],
)
def test_bad_or_not_yet_offered_arguments_raise_value_error(options):
    with pytest.raises(ValueError):
        hinge.conform_energy(tan_term(), **options)


def test_the_quadratic_isometric_bending_term_passes_on_flat_rest_hinges():
    r = hinge.conform_energy(quadratic_term(), energy="quadratic")
    assert r.passed, str(r)
    assert {c.split("/")[1] for c in r.categories} == {"flat", "at-rest"}
    assert r.settings["energy"] == "quadratic" and r.settings["weight"] == "none"


def test_bergous_half_quadratic_form_is_named_as_a_factor_one_half():
    # Bergou et al. 2006 write E = 1/2 x^T Q x with Q_e = 3 / A_bar K K^T: with the contract's k that is half.
    r = hinge.conform_energy(quadratic_term(constant=1.5), energy="quadratic")
    assert not r.passed
    assert "1/2 times the declared one" in sentence(r)


def test_the_html_reproducer_calls_the_term_with_its_rest_hinge_and_reproduces(tmp_path, monkeypatch):
    wrong = tan_term(weight=lambda R: contract_weight(R) / 3)
    path = tmp_path / "report.html"
    hinge.conform_energy(wrong).to_html(path)
    page = path.read_text()
    code = html.unescape(re.search(r'<pre class="pytest">(.*?)</pre>', page, re.S).group(1))
    assert "my_term(X.copy(), R.copy())" in code and "R = np.array(" in code and '"energy": np.array(' in code
    for term, fails in ((wrong, True), (tan_term(), False)):
        monkeypatch.setitem(sys.modules, "my_module", types.SimpleNamespace(my_term=term))
        namespace = {}
        exec(code, namespace)
        if fails:
            with pytest.raises(AssertionError):
                namespace["test_worst_case"]()
        else:
            namespace["test_worst_case"]()
