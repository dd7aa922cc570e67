"""hinge.hessian: the same energy, gradient and matrix as `hinge hessian --out --gradient`; bad
arguments and invalid meshes raise ValueError naming what is wrong."""

import os
import sys

import numpy as np
import pytest
import scipy.io
import scipy.sparse

import hinge
from conftest import MESHES, ROOT

sys.path.insert(0, os.path.join(ROOT, "scenes"))
from objmesh import read_obj  # noqa: E402 (the scene scripts' OBJ reader)


def write_obj(path, vertices, faces):
    with open(path, "w") as f:
        for v in vertices:
            f.write("v %r %r %r\n" % tuple(float(c) for c in v))
        for t in faces:
            f.write("f %d %d %d\n" % tuple(int(i) + 1 for i in t))


def bent_grid(n, seed=5):
    """An n x n grid of the unit square, two triangles per cell, lifted by a smooth bump plus noise."""
    rng = np.random.default_rng(seed)
    s = np.linspace(0.0, 1.0, n)
    u, v = np.meshgrid(s, s, indexing="ij")
    z = 0.3 * np.sin(3 * u) * np.cos(2 * v) + 1e-3 * rng.standard_normal(u.shape)
    vertices = np.column_stack([u.ravel(), v.ravel(), z.ravel()])
    faces = []
    for i in range(n - 1):
        for j in range(n - 1):
            a, b, c, d = i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1
            faces += [[a, b, c], [a, c, d]]
    return vertices, np.array(faces)


def command_outputs(command, tmp_path, mesh, rest, *args):
    out, gradient = str(tmp_path / "H.mtx"), str(tmp_path / "G.txt")
    extra = ["--rest", rest] if rest else []
    text = command("hessian", "--mesh", mesh, *extra, "--out", out, "--gradient", gradient, *args).decode()
    energy = float(text.split()[1])
    return energy, np.loadtxt(gradient), scipy.sparse.csr_matrix(scipy.io.mmread(out))


@pytest.mark.parametrize("energy,method,scalar", [("tan", "fast", "double"), ("shells", "reference", "double"),
                                                  ("tan", "fast", "long-double")])
def test_hessian_is_the_command_matrix_on_the_committed_mesh(command, tmp_path, energy, method, scalar):
    mesh, rest = os.path.join(MESHES, "hex.obj"), os.path.join(MESHES, "hex-rest.obj")
    expected = command_outputs(command, tmp_path, mesh, rest, "--energy", energy, "--k", "1.5", "--method", method,
                               "--scalar", scalar)
    vertices, faces = read_obj(mesh)
    rest_vertices, _ = read_obj(rest)
    e, g, H = hinge.hessian(vertices, faces, rest=rest_vertices, energy=energy, k=1.5, method=method, scalar=scalar)
    assert e == expected[0]
    np.testing.assert_array_equal(g, expected[1])
    assert isinstance(H, scipy.sparse.csr_matrix) and H.shape == expected[2].shape
    assert (H != expected[2]).nnz == 0
    assert (H != H.T).nnz == 0


def test_hessian_is_the_command_matrix_on_a_grid_with_threads(command, tmp_path):
    vertices, faces = bent_grid(21)
    mesh = str(tmp_path / "grid.obj")
    write_obj(mesh, vertices, faces)
    flat = vertices.copy()
    flat[:, 2] = 0
    rest = str(tmp_path / "flat.obj")
    write_obj(rest, flat, faces)
    expected = command_outputs(command, tmp_path, mesh, rest, "--energy", "tan", "--k", "2", "--method", "fast")
    for threads in (1, 2):
        e, g, H = hinge.hessian(vertices, faces, rest=flat, k=2.0, threads=threads)
        assert e == expected[0] and e > 0
        np.testing.assert_array_equal(g, expected[1])
        assert (H != expected[2]).nnz == 0


@pytest.mark.parametrize("change,message", [
    (lambda v, f: (v[:, :2], f), "shape \\(n, 3\\)"),
    (lambda v, f: (v, f[:, :2]), "shape \\(m, 3\\)"),
    (lambda v, f: (v, f + 0.5), "integers"),
    (lambda v, f: (v, f + 100), "refers to vertex"),
    (lambda v, f: (np.where(v == v[0, 0], np.nan, v), f), "not finite"),
    (lambda v, f: (v, f[:0]), "empty"),
    (lambda v, f: (v, np.vstack([f, f[:1]])), "edge"),
    (lambda v, f: (v, f[:1]), "no interior edge"),
    (lambda v, f: (v, [[0, 1, 2], [1, 3]]), "faces must be"),  # ragged
    (lambda v, f: (v, np.array([[0, 1, 2], [1, 3, 2**64 - 1]], dtype=np.uint64)), "vertex 18446744073709551615"),
])
def test_bad_meshes_raise_value_error_naming_the_problem(change, message):
    vertices, faces = bent_grid(4)
    v, f = change(vertices, faces)
    with pytest.raises(ValueError, match=message):
        hinge.hessian(v, f)


@pytest.mark.parametrize("kwargs,message", [({"energy": "bent"}, "bent"), ({"k": -1.0}, "k must"),
                                            ({"k": float("nan")}, "k must"), ({"method": "x"}, "method"),
                                            ({"threads": -2}, "threads"), ({"method": 3}, "method must be a string"),
                                            ({"threads": 2**40}, "threads must be in"), ({"k": "a"}, "k must be a number"),
                                            ({"energy": None}, "energy must be a string"), ({"threads": True}, "threads")])
def test_bad_parameters_raise_value_error(kwargs, message):
    vertices, faces = bent_grid(4)
    with pytest.raises(ValueError, match=message):
        hinge.hessian(vertices, faces, **kwargs)


def test_a_mesh_without_interior_edges_is_accepted_when_asked():
    vertices, faces = bent_grid(4)
    e, g, H = hinge.hessian(vertices, faces[:1], allow_no_hinges=True)
    assert e == 0 and not g.any() and H.nnz == 0
