"""hinge.conform_mesh (docs/mesh-conformance.md; contract, "Conformance of bending energies", bullet "Mesh
level"): whole-mesh candidates built from the project's own evaluator (hinge.hessian, within a few units of
2^-53 of the certified values), correct or with one known slip, so that what the report must say is known
exactly: which check fails, and for a wrong Hessian block which vertex pair and which hinges.

The hinges a report names are recomputed here from the faces alone (an interior edge, oriented as in the
first face that holds it, and its two opposite vertices), independently of hinge::build_topology.
"""

import inspect
import json
import math
import re
import subprocess
import sys

import numpy as np
import pytest

import hinge
from conftest import ROOT

PAGE = "docs/mesh-conformance.md"


def cylinder_grid(radius, twist, nx=4, ny=3):
    """A grid of nx x ny squares of side 1/2 with alternating diagonals rolled onto a cylinder about y and
    twisted (the same as the page's example)."""
    u, v = np.meshgrid(0.5 * np.arange(nx + 1) - nx / 4, 0.5 * np.arange(ny + 1) - ny / 4)
    u, v = u.ravel(), v.ravel()
    vertices = np.column_stack([radius * np.sin(u / radius), v, radius * (1 - np.cos(u / radius)) + twist * u * v])
    faces = []
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = j * (nx + 1) + i, j * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i
            faces += [[a, b, c], [a, c, d]] if (i + j) % 2 == 0 else [[a, b, d], [b, c, d]]
    return vertices, np.array(faces)


REST, FACES = cylinder_grid(radius=2.0, twist=0.0)  # curved at rest
VERTICES, _ = cylinder_grid(radius=1.25, twist=0.25)


def hinges_of(faces):
    """{(a, b): {a, b, opposite, other opposite}} per interior edge a -> b (its direction in its first face)."""
    first, opposite = {}, {}
    for face in faces:
        for k in range(3):
            a, b, o = int(face[(k + 1) % 3]), int(face[(k + 2) % 3]), int(face[k])
            key = frozenset((a, b))
            first.setdefault(key, (a, b))
            opposite.setdefault(key, []).append(o)
    return {first[key]: set(first[key]) | set(o) for key, o in opposite.items() if len(o) == 2}


def hinges_holding(faces, i, j):
    return {edge for edge, stencil in hinges_of(faces).items() if i in stencil and j in stencil}


def bending(V, faces, rest):
    return hinge.hessian(V, faces, rest, energy="tan", k=1.0)


def failing(report):
    return {(c["mesh"], c["check"]) for c in report.checks if not c["pass"]}


def check(report, name, mesh="mesh"):
    found = [c for c in report.checks if c["mesh"] == mesh and c["check"] == name]
    assert len(found) == 1, (name, [c["check"] for c in report.checks])
    return found[0]


# --- what passes


def test_the_projects_evaluator_passes_on_the_conformance_meshes_curved_rest_among_them():
    report = hinge.conform_mesh(bending)
    assert report.passed, str(report)
    names = [m["name"] for m in report.meshes]
    assert names == ["strip", "hex", "strip-curved-rest", "hex-curved-rest"]
    checks = {c["check"] for c in report.checks}
    assert {"energy", "gradient", "hessian", "net force", "net torque", "force at rest"} <= checks
    assert len([c for c in checks if c.startswith("energy under rigid motion")]) == 5
    assert len([c for c in checks if c.startswith("gradient turned with the motion")]) == 5
    for c in report.checks:  # well inside the tolerances, not at their edge
        assert c["error"] <= c["tolerance"] / 4, c


def test_the_projects_evaluator_passes_on_a_given_mesh_with_a_curved_rest_shape_for_every_energy():
    for energy in ("shells", "tan", "willmore", "bridson"):
        fn = lambda V, F, R: hinge.hessian(V, F, R, energy=energy, k=2.5)  # noqa: E731
        report = hinge.conform_mesh(fn, VERTICES, FACES, REST, energy=energy, k=2.5)
        assert report.passed, str(report)
        assert [m["hinges"] for m in report.meshes] == [len(hinges_of(FACES))]
        assert ("force at rest" in {c["check"] for c in report.checks}) == (energy != "willmore")


def test_the_certified_values_pass_whatever_the_hessians_storage():
    """A dense array and a scipy.sparse matrix in another format are the same Hessian."""
    for convert in (lambda H: H.toarray(), lambda H: H.tocoo(), lambda H: H.tolil()):

        def fn(V, F, R):
            e, g, H = bending(V, F, R)
            return e, g.reshape(-1, 3), convert(H)

        assert hinge.conform_mesh(fn, VERTICES, FACES, REST).passed


# --- what fails, and where


def test_a_hessian_wrong_in_one_vertex_pair_fails_naming_exactly_those_vertices_and_the_hinges_holding_both():
    # Vertices 7 and 8 share an edge: several hinges hold both. Scale their off-diagonal block by 1.01.
    i, j = 7, 8
    assert len(hinges_holding(FACES, i, j)) > 1

    def fn(V, F, R):
        e, g, H = bending(V, F, R)
        H = H.toarray()
        H[3 * i:3 * i + 3, 3 * j:3 * j + 3] *= 1.01
        H[3 * j:3 * j + 3, 3 * i:3 * i + 3] *= 1.01
        return e, g, H

    report = hinge.conform_mesh(fn, VERTICES, FACES, REST)
    assert not report.passed
    assert failing(report) == {("mesh", "hessian")}
    c = check(report, "hessian")
    assert c["vertices"] == (i, j)
    assert set(c["hinges"]) == hinges_holding(FACES, i, j)
    assert f"the worst 3 x 3 block at vertices ({i}, {j})" in str(report)


def test_a_block_only_one_hinge_couples_names_that_one_hinge():
    # The two opposite vertices of the hinge of edge (0, 6): only that hinge holds both.
    (edge,) = [e for e, s in hinges_of(FACES).items() if {1, 5} <= s]
    assert set(edge) == {0, 6}

    def fn(V, F, R):
        e, g, H = bending(V, F, R)
        H = H.tolil()
        for a, b in ((1, 5), (5, 1)):
            H[3 * a:3 * a + 3, 3 * b:3 * b + 3] = H[3 * a:3 * a + 3, 3 * b:3 * b + 3].toarray() * 1.01
        return e, g, H.tocsr()

    c = check(hinge.conform_mesh(fn, VERTICES, FACES, REST), "hessian")
    assert not c["pass"] and c["vertices"] == (1, 5) and c["hinges"] == [edge]


def test_an_asymmetric_hessian_fails_even_where_its_upper_triangle_is_right():
    def fn(V, F, R):
        e, g, H = bending(V, F, R)
        H = H.toarray()
        H[3 * 8:3 * 8 + 3, 3 * 7:3 * 7 + 3] *= 1.01  # the lower block (8, 7) only
        return e, g, H

    c = check(hinge.conform_mesh(fn, VERTICES, FACES, REST), "hessian")
    assert not c["pass"] and c["vertices"] == (7, 8)


def test_an_upper_triangle_alone_fails_and_the_report_says_the_full_matrix_is_wanted():
    def fn(V, F, R):
        e, g, H = bending(V, F, R)
        return e, g, np.triu(H.toarray())

    c = check(hinge.conform_mesh(fn, VERTICES, FACES, REST), "hessian")
    assert not c["pass"] and "full symmetric Hessian" in c["detail"]


def test_a_wrong_gradient_fails_naming_its_vertex():
    def fn(V, F, R):
        e, g, H = bending(V, F, R)
        g = g.copy()
        g[3 * 12 + 2] *= 1 + 1e-9  # vertex 12, z
        return e, g, H

    report = hinge.conform_mesh(fn, VERTICES, FACES, REST)
    assert failing(report) == {("mesh", "gradient")}
    c = check(report, "gradient")
    assert c["vertices"] == (12, 12)
    assert set(c["hinges"]) == hinges_holding(FACES, 12, 12)
    assert "the largest difference at vertex 12" in str(report)


def test_a_wrong_energy_fails():
    def fn(V, F, R):
        e, g, H = bending(V, F, R)
        return e * (1 + 1e-12), g, H

    report = hinge.conform_mesh(fn, VERTICES, FACES, REST)
    assert failing(report) == {("mesh", "energy")}


def test_a_candidate_with_a_force_at_rest_fails_the_at_rest_check():
    # Its rest angles are off: it reads the rest shape stretched by 1% along z (the weights barely change,
    # the angles do), so that fn(rest, faces, rest) has a force.
    def fn(V, F, R):
        return bending(V, F, R * [1, 1, 1.01])

    report = hinge.conform_mesh(fn, VERTICES, FACES, REST)
    c = check(report, "force at rest")
    assert not c["pass"] and c["error"] > 1e6 * c["tolerance"]
    assert "vertices" in c and "hinges" in c


def test_a_force_that_is_not_invariant_fails_the_rigid_motion_and_net_load_checks():
    # A gravity-like term on the energy: not invariant under rotation and with a net force.
    def fn(V, F, R):
        e, g, H = bending(V, F, R)
        weight = 1e-3 * np.tile([0.0, 0.0, 1.0], len(V))
        return e + float(weight @ V.ravel()), g + weight, H

    report = hinge.conform_mesh(fn, VERTICES, FACES, REST)
    failed = {name for _, name in failing(report)}
    assert {"energy", "gradient", "net force"} <= failed
    assert "energy under rigid motion (quarter turn about x)" in failed
    assert "energy under rigid motion (translation)" in failed
    assert "energy under rigid motion (quarter turn about z)" not in failed  # z is kept by it


def test_the_exact_hessian_declared_as_gauss_newton_fails_only_the_hessian():
    report = hinge.conform_mesh(bending, VERTICES, FACES, REST, hessian="gauss-newton")
    assert failing(report) == {("mesh", "hessian")}


def test_a_nan_in_the_outputs_is_a_failure_reported_as_such():
    def fn(V, F, R):
        e, g, H = bending(V, F, R)
        H = H.toarray()
        H[3 * 4, 3 * 9] = H[3 * 9, 3 * 4] = math.nan
        return e, g, H

    report = hinge.conform_mesh(fn, VERTICES, FACES, REST)
    assert not report.passed
    c = check(report, "hessian")
    assert not c["pass"] and math.isnan(c["error"]) and c["detail"] == "a NaN in the candidate's hessian"
    assert c["vertices"] == (4, 9)
    assert json.loads(report.to_json())["checks"][2]["error"] is None

    def nan_gradient(V, F, R):
        e, g, H = bending(V, F, R)
        return e, g * math.nan, H

    report = hinge.conform_mesh(nan_gradient, VERTICES, FACES, REST)
    failed = {name for _, name in failing(report)}
    assert {"gradient", "net force", "net torque", "force at rest"} <= failed
    assert "gradient turned with the motion (translation)" in failed


def test_a_candidate_that_raises_fails_the_checks_of_that_call():
    def fn(V, F, R):
        if np.array_equal(V, R):
            raise RuntimeError("no rest state")
        return bending(V, F, R)

    report = hinge.conform_mesh(fn, VERTICES, FACES, REST)
    assert failing(report) == {("mesh", "force at rest")}
    assert check(report, "force at rest")["detail"] == "fn raised RuntimeError: no rest state (at rest)"


# --- the report


def test_the_report_as_text_and_json():
    report = hinge.conform_mesh(bending, VERTICES, FACES, REST, energy="tan", k=1.0)
    text = str(report)
    assert text.startswith("hinge conform_mesh: Python function bending (energy tan, weight contract, k 1.0")
    assert text.endswith("PASS: 0 of 16 checks failed")
    parsed = json.loads(report.to_json())
    assert parsed["passed"] is True and parsed["unit"] == "2^-53"
    assert [c["check"] for c in parsed["checks"]] == [c["check"] for c in report.checks]
    assert parsed["options"] == {"candidate": "Python function bending", "energy": "tan", "weight": "contract",
                                 "k": 1.0, "hessian": "exact"}
    assert report.candidate_seconds > 0 and report.kit_seconds > 0


def test_without_rest_the_mesh_is_its_own_rest_shape_and_the_report_says_so():
    report = hinge.conform_mesh(bending, VERTICES, FACES)
    assert report.passed
    assert "rest= not given: the mesh is its own rest shape" in report.notes


# --- bad arguments


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"energy": "quadratic"}, "not graded at mesh level yet"),
        ({"energy": "custom"}, "not graded at mesh level yet"),
        ({"energy": "springs"}, "unknown energy 'springs'"),
        ({"energy": "viscoelastic"}, "library-only"),
        ({"energy": 3}, "energy= must be a string"),
        ({"weight": "bridson"}, "grades only weight='contract'"),
        ({"weight": lambda R: np.ones(len(R))}, "grades only weight='contract'"),
        ({"hessian": "projected"}, "projected Hessian is not graded at mesh level"),
        ({"hessian": "newton"}, "hessian= must be 'exact' or 'gauss-newton'"),
        ({"k": -1.0}, "k=: the bending stiffness k must be finite and >= 0"),
        ({"k": "1"}, "k= must be a number"),
        ({"k": True}, "k= must be a number"),
    ],
)
def test_bad_options_raise_value_error_naming_them(kwargs, message):
    with pytest.raises(ValueError, match=re.escape(message)):
        hinge.conform_mesh(bending, VERTICES, FACES, REST, **kwargs)


@pytest.mark.parametrize(
    "args, message",
    [
        ((VERTICES[:, :2], FACES, REST), "vertices must have shape (n, 3)"),
        ((VERTICES, FACES, REST[:-1]), "rest has 19 vertices, vertices has 20"),
        ((VERTICES, FACES[:, :2], REST), "faces must have shape (m, 3)"),
        ((VERTICES, FACES + 0.5, REST), "faces must hold integers"),
        ((VERTICES, FACES + 20, REST), "faces[0] refers to vertex 20, but there are 20 vertices"),
        ((VERTICES, np.zeros((0, 3), int), REST), "faces is empty"),
        ((VERTICES, None, REST), "faces= is required with vertices="),
        ((None, FACES, None), "faces= and rest= need vertices="),
        ((np.where(np.arange(60).reshape(20, 3) == 4, np.nan, VERTICES), FACES, REST), "vertices[1] is not finite"),
        ((VERTICES, FACES[:1], REST), "the mesh has no interior edge"),
        ((VERTICES * [1, 1, 0] * 0, FACES, REST), "has zero area"),
    ],
)
def test_bad_meshes_raise_value_error_naming_what_is_wrong(args, message):
    with pytest.raises(ValueError, match=re.escape(message)):
        hinge.conform_mesh(bending, *args)


def test_a_bad_candidate_raises_value_error_naming_its_output():
    with pytest.raises(ValueError, match="fn must be callable"):
        hinge.conform_mesh(None, VERTICES, FACES, REST)
    cases = [
        (lambda V, F, R: bending(V, F, R)[:2], "fn must return (energy, gradient"),
        (lambda V, F, R: (1.0, np.zeros(5), np.zeros((60, 60))), "a gradient of shape (5,)"),
        (lambda V, F, R: (np.zeros(2), np.zeros(60), np.zeros((60, 60))), "an energy of shape (2,)"),
        (lambda V, F, R: (1.0, np.zeros(60), np.zeros((60, 59))), "a Hessian of shape (60, 59)"),
        (lambda V, F, R: (1.0, np.zeros(60).astype(str), np.zeros((60, 60))), "a gradient of shape (60,) and dtype <U"),
    ]
    for fn, message in cases:
        with pytest.raises(ValueError, match=re.escape(message)):
            hinge.conform_mesh(fn, VERTICES, FACES, REST)


# --- the page


def test_the_pages_example_prints_what_the_page_shows():
    with open(f"{ROOT}/{PAGE}") as f:
        page = f.read()
    (script,) = re.findall(r"```python\n(.*?)```", page, re.S)
    shown = re.findall(r"```text\n(.*?)```", page, re.S)
    assert len(shown) == 2, "the page's blocks changed: update this test"
    assert inspect.getsource(cylinder_grid).split('"""')[2] in script  # this file's mesh is the page's
    result = subprocess.run([sys.executable, "-c", script], cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert result.returncode == 0, result.stderr.decode()
    printed = re.split(r"(?m)^(?=hinge conform_mesh: )", result.stdout.decode())
    assert printed[0] == "" and printed[1:] == shown  # print() ends each report with a newline
