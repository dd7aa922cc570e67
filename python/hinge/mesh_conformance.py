"""Whole-mesh conformance from Python: check a simulator's bending energy, force and Hessian on a whole mesh
(docs/mesh-conformance.md; contract, "Conformance of bending energies", bullet "Mesh level").

``conform_mesh(fn)`` calls ``fn(V, faces, rest)`` on a mesh (the project's conformance meshes by default),
and grades what it returns against the certified mesh values (the double nearest the exact value of every
output), then checks that its energy is unchanged and its gradient turned by rigid motions, that its net
force and torque are zero, and that its force at rest is zero. The certified values, the comparisons and
the checks are hinge::oracle's and hinge::conformance's (``_hinge.MeshProblem``): this module only calls the
candidate and converts its arrays.
"""

import json
import math
import time

import numpy as np

from . import _hinge

__all__ = ["conform_mesh", "MeshReport"]

_UNIT = "2^-53"


class MeshReport:
    """The graded run of ``conform_mesh``.

    ``passed``: True when every check passes. ``checks``: a list of dicts, one per mesh and check, with
    ``mesh``, ``check``, ``error``, ``tolerance`` (both in units of 2^-53, relative to the check's scale:
    docs/mesh-conformance.md; ``error`` is NaN where the candidate's output holds a NaN or ``fn`` raised),
    ``pass``, where a gradient or Hessian fails ``vertices`` (i, j), the vertex pair of the worst 3 x 3 block
    of candidate - certified ((v, v) for a gradient's vertex v) and ``hinges``, the hinges holding both, each
    as its edge's vertex indices (i, j), and where there is something to say ``detail``. ``notes``: what
    else to know. ``options``: what was graded. ``meshes``: per mesh its ``name``, ``vertices`` and
    ``hinges`` counts. ``candidate_seconds`` and ``kit_seconds``: the time spent in ``fn`` and in the kit.
    ``str(report)`` is a text report (no times in it: the same text on every run), ``to_json()`` the same as
    JSON (with the times).
    """

    def __init__(self, options, meshes, checks, notes, candidate_seconds, kit_seconds):
        self.options = options
        self.meshes = meshes
        self.checks = checks
        self.notes = notes
        self.passed = all(c["pass"] for c in checks)
        self.candidate_seconds = candidate_seconds
        self.kit_seconds = kit_seconds

    def failures(self):
        """The checks that did not pass."""
        return [c for c in self.checks if not c["pass"]]

    def to_json(self):
        """The report as a JSON object (a NaN or infinite error is null)."""

        def finite(value):
            return value if isinstance(value, float) and math.isfinite(value) else None

        checks = []
        for c in self.checks:
            entry = dict(c, error=finite(c["error"]), tolerance=finite(c["tolerance"]))
            if "vertices" in entry:
                entry["vertices"] = list(entry["vertices"])
                entry["hinges"] = [list(h) for h in entry["hinges"]]
            checks.append(entry)
        return json.dumps(
            {
                "passed": self.passed,
                "options": self.options,
                "unit": _UNIT,
                "meshes": self.meshes,
                "checks": checks,
                "notes": self.notes,
                "candidate_seconds": self.candidate_seconds,
                "kit_seconds": self.kit_seconds,
            },
            indent=1,
            allow_nan=False,
        )

    def __str__(self):
        o = self.options
        lines = [
            f"hinge conform_mesh: {o['candidate']} (energy {o['energy']}, weight {o['weight']}, k {o['k']!r}, "
            f"hessian {o['hessian']})",
            "meshes: "
            + ", ".join(f"{m['name']} ({m['vertices']} vertices, {m['hinges']} hinges)" for m in self.meshes),
            f"errors and tolerances in units of {_UNIT}, relative to each check's scale (docs/mesh-conformance.md)",
            "",
        ]
        width_mesh = max([4] + [len(c["mesh"]) for c in self.checks])
        width_check = max([5] + [len(c["check"]) for c in self.checks])
        lines.append(f"{'mesh':<{width_mesh}}  {'check':<{width_check}}  {'error':>10}  {'tolerance':>10}  result")
        for c in self.checks:
            lines.append(
                f"{c['mesh']:<{width_mesh}}  {c['check']:<{width_check}}  {_number(c['error']):>10}  "
                f"{_number(c['tolerance']):>10}  {'ok' if c['pass'] else 'FAIL'}"
            )
        failures = self.failures()
        if failures:
            lines.append("")
        for c in failures:
            text = f"FAIL {c['mesh']}, {c['check']}: error {_number(c['error'])} > tolerance {_number(c['tolerance'])}"
            if "vertices" in c:
                i, j = c["vertices"]
                where = f"vertex {i}" if i == j else f"vertices ({i}, {j})"
                what = "the largest difference" if i == j else "the worst 3 x 3 block"
                hinges = ", ".join(f"({a}, {b})" for a, b in c["hinges"]) or "none"
                text += f"; {what} at {where}, in the hinges (edge vertices) {hinges}"
            if "detail" in c:
                text += f" ({c['detail']})"
            lines.append(text)
        if self.notes:
            lines.append("")
            lines.extend(f"note: {n}" for n in self.notes)
        lines.append("")
        lines.append(f"{'PASS' if self.passed else 'FAIL'}: {len(failures)} of {len(self.checks)} checks failed")
        return "\n".join(lines)

    def __repr__(self):
        verdict = "passed" if self.passed else "not passed"
        return f"<hinge mesh conformance report: {verdict}, {len(self.checks)} checks>"


def _number(value):
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if value == 0 or 1e-3 <= abs(value) < 1e6:
        return f"{value:.1f}" if value >= 0.05 or value == 0 else f"{value:.3g}"
    return f"{value:.3g}"


def _vertices(value, name, rows=None):
    """`value` as a fresh C-contiguous float64 (n, 3) array; ValueError naming `name` otherwise."""
    try:
        a = np.array(value, dtype=np.float64, order="C")
    except (TypeError, ValueError) as e:
        raise ValueError(f"{name} must be convertible to a float64 array of shape (n, 3): {e}") from None
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"{name} must have shape (n, 3); got {a.shape}")
    if rows is not None and a.shape[0] != rows:
        raise ValueError(f"{name} has {a.shape[0]} vertices, vertices has {rows}")
    bad = np.flatnonzero(~np.isfinite(a).all(axis=1))
    if bad.size:
        raise ValueError(f"{name}[{bad[0]}] is not finite")
    return a


def _faces(value, vertex_count):
    """`value` as a fresh (m, 3) int64 array of 0-based indices; ValueError naming what is wrong."""
    a = np.asarray(value)
    if a.ndim != 2 or a.shape[1] != 3:
        raise ValueError(f"faces must have shape (m, 3); got {a.shape}")
    if a.shape[0] == 0:
        raise ValueError("faces is empty: a mesh needs at least one face")
    if a.dtype.kind not in "iu":
        raise ValueError(f"faces must hold integers (0-based vertex indices); got dtype {a.dtype}")
    outside = np.argwhere((a < 0) | (a >= vertex_count))
    if outside.size:
        f, c = outside[0]
        raise ValueError(
            f"faces[{f}] refers to vertex {a[f, c]}, but there are {vertex_count} vertices (0-based)"
        )
    return np.array(a, dtype=np.int64, order="C")


def _unpack(result, n):
    """The candidate's (energy, gradient, hessian) as (float, (3n,) float64, (rows, cols, values) of the full
    Hessian, which outputs hold a NaN or an infinity); ValueError for a wrong shape or type."""
    if isinstance(result, dict):
        missing = [key for key in ("energy", "gradient", "hessian") if key not in result]
        if missing:
            raise ValueError(f"fn returned a dict without {', '.join(missing)}")
        result = (result["energy"], result["gradient"], result["hessian"])
    if not isinstance(result, (tuple, list)) or len(result) != 3:
        raise ValueError("fn must return (energy, gradient (3n,), Hessian (3n, 3n)); got " + type(result).__name__)
    energy, gradient, hessian = result
    e = np.asarray(energy)
    if e.dtype.kind not in "fiu" or e.size != 1:
        raise ValueError(f"fn returned an energy of shape {e.shape} and dtype {e.dtype}; expected a real number")
    e = float(e.reshape(()))
    g = np.asarray(gradient)
    if g.dtype.kind not in "fiu" or g.shape not in ((3 * n,), (n, 3)):
        raise ValueError(
            f"fn returned a gradient of shape {g.shape} and dtype {g.dtype}; expected a real array of shape "
            f"({3 * n},) (or ({n}, 3))"
        )
    g = np.ascontiguousarray(g, dtype=np.float64).reshape(3 * n)
    size = (3 * n, 3 * n)
    if hasattr(hessian, "tocoo"):  # scipy.sparse, or anything that converts to coordinates
        coo = hessian.tocoo()
        shape = tuple(coo.shape)
        rows, cols, values = np.asarray(coo.row), np.asarray(coo.col), np.asarray(coo.data)
    else:
        dense = np.asarray(hessian.toarray() if hasattr(hessian, "toarray") else hessian)
        shape = dense.shape
        rows, cols = np.nonzero(dense) if dense.ndim == 2 else (np.zeros(0), np.zeros(0))
        values = dense[rows, cols] if dense.ndim == 2 else np.zeros(0)
    if shape != size or values.dtype.kind not in "fiu":
        raise ValueError(
            f"fn returned a Hessian of shape {shape} and dtype {values.dtype}; expected a real scipy.sparse matrix "
            f"or dense array of shape {size}"
        )
    bad = {
        name: ("a NaN" if np.isnan(v).any() else "an infinity")
        for name, v in (("energy", np.array([e])), ("gradient", g), ("hessian", values.astype(np.float64)))
        if not np.isfinite(v).all()
    }
    hess = (
        np.ascontiguousarray(rows, dtype=np.int64),
        np.ascontiguousarray(cols, dtype=np.int64),
        np.ascontiguousarray(values, dtype=np.float64),
    )
    return e, g, hess, bad


def _describe(e):
    text = str(e)
    return f"fn raised {type(e).__name__}" + (f": {text}" if text else "")


def _not_evaluated(names, reason):
    """Failed checks for `names`: the call they need could not be evaluated (`reason`)."""
    return [
        {"check": name, "error": math.nan, "tolerance": math.nan, "pass": False, "detail": reason} for name in names
    ]


def conform_mesh(fn, vertices=None, faces=None, rest=None, *, energy="tan", weight="contract", k=1.0, hessian="exact"):
    """Grade a whole-mesh bending energy, its gradient and its Hessian against certified values.

    fn(V, faces, rest): V and rest fresh (n, 3) float64 arrays (the deformed and the rest vertices), faces a
    fresh (m, 3) int64 array (0-based, counter-clockwise); it returns (energy, gradient, Hessian): the energy
    a real number, the gradient (3n,) (or (n, 3)), global index 3 v + c, the Hessian the full symmetric
    3n x 3n matrix as a scipy.sparse matrix (anything with .tocoo() or .toarray()) or a dense array. A tuple
    or a dict with the keys "energy", "gradient", "hessian".

    vertices, faces, rest: the mesh (rest defaults to vertices: the mesh at rest). Without vertices, the
    project's conformance meshes: each of hinge::conformance::meshes() (flat rest), and each again with its
    rest and deformed shapes exchanged ("<name>-curved-rest").
    energy: "shells", "tan", "willmore" or "bridson" (docs/quantities.md); weight: "contract" (w = 3
    |e_bar|^2 / A_bar, the only weight graded at mesh level); k: the stiffness (finite, >= 0); hessian:
    "exact" or "gauss-newton" (sum over hinges of psi'' grad theta grad theta^T).

    Checks per mesh (docs/mesh-conformance.md): the energy, gradient and Hessian against the certified ones;
    the energy unchanged and the gradient turned under five rigid motions of V; zero net force and torque;
    zero force at rest (fn(rest, faces, rest); not for willmore, whose force at rest is not zero).

    Returns a MeshReport. A NaN in the candidate's outputs, or fn raising an Exception, fails the checks that
    need that call, and the report says so. Raises ValueError for a bad argument (naming it), an invalid
    mesh, or an output of the wrong shape or type.
    """
    start = time.perf_counter()
    if not callable(fn):
        raise ValueError(f"fn must be callable; got {type(fn).__name__}")
    if isinstance(k, (bool, np.bool_)) or not isinstance(k, (int, float, np.integer, np.floating)):
        raise ValueError(f"k= must be a number; got {type(k).__name__}")
    for value, name in ((energy, "energy"), (hessian, "hessian")):
        if not isinstance(value, str):
            raise ValueError(f"{name}= must be a string; got {type(value).__name__}")
    notes = []
    if vertices is None:
        if faces is not None or rest is not None:
            raise ValueError("faces= and rest= need vertices= (without vertices, the conformance meshes are graded)")
        cases = [tuple(c) for c in _hinge.mesh_conformance_meshes()]
    else:
        if faces is None:
            raise ValueError("faces= is required with vertices=")
        v = _vertices(vertices, "vertices")
        f = _faces(faces, len(v))
        if rest is None:
            notes.append("rest= not given: the mesh is its own rest shape")
            r = v.copy()
        else:
            r = _vertices(rest, "rest", rows=len(v))
        cases = [("mesh", v, f, r)]
    # Every mesh certified before fn is called: a bad argument raises before any work of the candidate.
    problems = [
        (name, v, f, r, _hinge.MeshProblem(v, f, r, energy, weight, float(k), hessian)) for name, v, f, r in cases
    ]

    candidate_seconds = 0.0

    def call(v, f, r):
        nonlocal candidate_seconds
        t = time.perf_counter()
        try:
            return fn(v.copy(), f.copy(), r.copy())
        finally:
            candidate_seconds += time.perf_counter() - t

    def evaluate(v, f, r, n):
        """(energy, gradient, hessian, bad) of fn at v, or the reason it could not be evaluated."""
        try:
            result = call(v, f, r)
        except Exception as e:  # noqa: BLE001 (a raising candidate is graded, not propagated)
            return None, _describe(e)
        return _unpack(result, n), None

    checks, meshes = [], []
    for name, v, f, r, problem in problems:
        n = problem.vertex_count
        meshes.append({"name": name, "vertices": n, "hinges": problem.hinge_count})
        if problem.uncertified:
            notes.append(f"{name}: outputs not certified within the oracle's precision cap: {problem.uncertified}")
        mesh_checks = []
        main, reason = evaluate(v, f, r, n)
        motions = problem.motions()
        motion_names = [
            f"{what} ({motion})"
            for motion, _ in motions
            for what in ("energy under rigid motion", "gradient turned with the motion")
        ]
        if main is None:
            mesh_checks += _not_evaluated(["energy", "gradient", "hessian"] + motion_names, reason)
            mesh_checks += _not_evaluated(["net force", "net torque"], reason)
        else:
            e0, g0, (rows, cols, values), bad = main
            for c in problem.compare(e0, g0, rows, cols, values):
                if c["check"] in bad:
                    c["detail"] = f"{bad[c['check']]} in the candidate's {c['check']}"
                mesh_checks.append(c)
            for index, (motion, moved) in enumerate(motions):
                out, reason = evaluate(moved, f, r, n)
                if out is None:
                    mesh_checks += _not_evaluated(motion_names[2 * index:2 * index + 2], reason + " (moved mesh)")
                    continue
                e1, g1, _, bad1 = out
                found = problem.check_motion(index, e0, g0, e1, g1)
                for c in found:
                    sources = {"energy", "gradient"} & (set(bad) | set(bad1))
                    if not c["pass"] and sources:
                        c["detail"] = "not finite: " + ", ".join(sorted(sources)) + " (at V or after the motion)"
                mesh_checks += found
            for c in problem.check_net_load(g0):
                if not c["pass"] and "gradient" in bad:
                    c["detail"] = f"{bad['gradient']} in the candidate's gradient"
                mesh_checks.append(c)
        if problem.zero_force_at_rest:
            out, reason = evaluate(r, f, r, n)
            if out is None:
                mesh_checks += _not_evaluated(["force at rest"], reason + " (at rest)")
            else:
                c = problem.check_at_rest(out[1])
                if "gradient" in out[3]:
                    c["detail"] = f"{out[3]['gradient']} in the candidate's gradient at rest"
                mesh_checks.append(c)
        checks += [dict({"mesh": name}, **c) for c in mesh_checks]
    if not problems[0][4].zero_force_at_rest:
        notes.append("force at rest not checked: the willmore energy has no rest angle (its force at rest is not zero)")
    options = {
        "candidate": f"Python function {getattr(fn, '__qualname__', None) or type(fn).__name__}",
        "energy": energy,
        "weight": weight,
        "k": float(k),
        "hessian": hessian,
    }
    total = time.perf_counter() - start
    return MeshReport(options, meshes, checks, notes, candidate_seconds, total - candidate_seconds)
