"""Conformance from Python: check a bending kernel in its own conventions (docs/python-conformance.md).

``conform(fn)`` calls ``fn`` on the conformance set, in the kernel's own vertex order and floating-point
type, maps its gradient and Hessian back to the contract's order, and grades them against certified
values with the tolerance policy of ``hinge conform`` (the same grading, tiers, diagnosis and reports:
this module only calls the candidate and converts its arrays).
"""

import math
import time

import numpy as np

from . import _hinge

__all__ = ["conform", "conform_energy", "Report", "OUTPUTS", "ENERGY_OUTPUTS", "ENERGIES", "LABELS"]

OUTPUTS = ("theta", "grad", "hess")
ENERGY_OUTPUTS = ("energy", "grad", "hess")
ENERGIES = ("shells", "tan", "willmore", "bridson", "quadratic", "custom")
LABELS = ("x0", "x1", "x2", "x3")
_SHAPES = {
    "theta": ((), "(n,)"),
    "energy": ((), "(n,)"),
    "grad": ((12,), "(n, 12)"),
    "hess": ((144,), "(n, 12, 12) or (n, 144)"),
}
_MISSING, _ERROR, _NONFINITE, _OK = 0, 1, 2, 3  # io::EvalOutput::Status


class Report:
    """The graded run: ``passed``, ``tier``, ``categories``, ``diagnosis``, ``notes``, ``to_json()``, ``to_html(path)``,
    ``str(report)`` (the text report of ``hinge conform``), and the time taken: ``candidate_seconds``
    (inside ``fn``) and ``kit_seconds`` (the rest). A bending energy's report (``conform_energy``) also has
    ``settings`` (energy, weight, k, hessian, blocks) and ``checks`` (the consistency checks, one dict each:
    check, id, discrepancy, estimate, threshold, pass, detail); its ``tier`` is None for ``energy="custom"``."""

    def __init__(self, compiled, candidate_seconds, kit_seconds):
        import json

        self._compiled = compiled
        self._json = compiled.json()
        parsed = json.loads(self._json)
        given = set(parsed["given"])
        settings = parsed.get("settings", {})  # a bending energy's report: energy, weight, k, hessian, blocks
        groups = ENERGY_OUTPUTS if settings else OUTPUTS
        self.passed = bool(compiled.passed)
        self.tier = None if settings.get("energy") == "custom" else compiled.tier
        self.diagnosis = list(compiled.diagnosis)
        self.notes = list(parsed["notes"])
        self.settings = dict(settings)
        self.checks = list(parsed.get("consistency", []))
        self.categories = {}
        for c in parsed["categories"]:
            entry = {"cases": c["cases"], "missing": c["missing"], "nonfinite": c["nonfinite"], "tier": c["tier"]}
            for group in groups:  # JSON's null: infinite (a missing result) for a group given, else not checked
                entry[group] = {
                    key: (math.inf if value is None else value) if group in given else None
                    for key, value in (("median", c["median"][group]), ("max", c["worst"][group]))
                }
            entry["worst_case"] = c["worst_case_detail"]
            self.categories[c["category"]] = entry
        self.candidate_seconds = candidate_seconds
        self.kit_seconds = kit_seconds

    def to_json(self):
        """The JSON report: exactly what ``hinge conform --json`` writes."""
        return self._json

    def to_html(self, path):
        """Writes the report as one self-contained HTML page to ``path``."""
        self._compiled.write_html(str(path))

    def __str__(self):
        return self._compiled.text()

    def __repr__(self):
        return f"<hinge conformance report: {self.tier}, {'passed' if self.passed else 'not passed'}>"


def _stencil_indices(stencil):
    if not isinstance(stencil, (tuple, list)):
        raise ValueError(f"stencil= must be a sequence of the four labels x0, x1, x2, x3; got {stencil!r}")
    labels = list(stencil)
    for label in labels:
        if label not in LABELS:
            raise ValueError(f"stencil=: unknown label {label!r} (expected 'x0', 'x1', 'x2' or 'x3')")
    if len(labels) != 4 or len(set(labels)) != 4:
        raise ValueError(f"stencil= must be a permutation of ('x0', 'x1', 'x2', 'x3'); got {tuple(labels)!r}")
    return [LABELS.index(label) for label in labels]


def _outputs(outputs, all_names=OUTPUTS):
    if isinstance(outputs, str):
        outputs = (outputs,)
    try:
        names = tuple(outputs)
    except TypeError:
        raise ValueError(f"outputs= must be a sequence of output names; got {outputs!r}") from None
    first = all_names[0]
    for name in names:
        if name not in all_names:
            raise ValueError(f"outputs=: unknown output {name!r} (expected {first!r}, 'grad' or 'hess')")
    if len(set(names)) != len(names) or set(names) not in ({first}, {first, "grad"}, set(all_names)):
        raise ValueError(
            f"outputs= must be {all_names!r}, ({first!r}, 'grad') or ({first!r},) (in any order); got {names!r}"
        )
    return names


def _dtype(dtype):
    try:
        name = None if dtype is None else np.dtype(dtype).name
    except TypeError:
        name = None
    if name not in ("float64", "float32"):
        raise ValueError(f"dtype= must be 'float64' or 'float32'; got {dtype!r}")
    return name


def _choice(value, name, choices):
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"{name}= must be one of {', '.join(repr(c) for c in choices)}; got {value!r}")
    return value


def _as_output(value, name, rows, batched):
    """The candidate's output `name` as a float64 array (rows, size); ValueError for a wrong shape or type."""
    try:
        a = np.asarray(value)
    except Exception as e:  # noqa: BLE001 (any conversion failure is the candidate's wrong output)
        raise ValueError(f"fn returned {name} that NumPy cannot convert: {e}") from None
    if a.dtype.kind not in "fiu":
        raise ValueError(f"fn returned {name} of dtype {a.dtype}; expected a real array of shape {_SHAPES[name][1]}")
    tail, shown = _SHAPES[name]
    original = tuple(a.shape)
    scalar = name in ("theta", "energy")
    if not batched:  # one hinge: theta (or energy) a scalar (or (1,)), grad (12,), hess (12, 12) or (144,)
        a = a if (scalar and original == (1,)) else a.reshape((1,) + original)
        shown = "() or (1,)" if scalar else {"grad": "(12,)", "hess": "(12, 12) or (144,)"}[name]
    size = int(np.prod(tail))
    ok = a.ndim >= 1 and a.shape[0] == rows and (a.shape[1:] == tail or (name == "hess" and a.shape[1:] == (12, 12)))
    if not ok:
        where = f" for one hinge" if not batched else f" for n = {rows} hinges"
        raise ValueError(f"fn returned {name} of shape {original}{where}; expected {shown}")
    return np.asarray(a, dtype=np.float64).reshape(rows, size)


def _unpack(result, names, rows, batched):
    if isinstance(result, dict):
        missing = [n for n in names if n not in result]
        if missing:
            raise ValueError(f"fn returned a dict without {', '.join(missing)} (outputs={names!r})")
        values = [result[n] for n in names]
    elif isinstance(result, (tuple, list)) and len(names) > 1:
        if len(result) != len(names):
            raise ValueError(f"fn returned {len(result)} values; expected {len(names)}, in the order of outputs={names!r}")
        values = list(result)
    elif len(names) == 1 and isinstance(result, tuple) and len(result) == 1:
        values = list(result)
    elif len(names) == 1:  # the one output itself: an array, a list, anything numpy.asarray takes
        values = [result]
    else:
        raise ValueError(f"fn must return a dict keyed by {names!r} or a tuple in that order; got {type(result).__name__}")
    return {n: _as_output(v, n, rows, batched) for n, v in zip(names, values)}


def _describe(e):
    text = str(e)
    return f"fn raised {type(e).__name__}" + (f": {text}" if text else "")


class _Calls:
    """Calls a candidate on rows of hinges and collects its outputs (shared by conform and conform_energy).

    run(inputs, columns): `inputs` a tuple of (n, 12) arrays (the candidate's order and dtype), passed to fn as
    fn(*inputs) in one batch, or (batch=False) one hinge at a time, shape (12,); a raising batch is retried
    hinge by hinge, shape (1, 12), with a note. Returns the outputs in the contract's order (value (n,), grad
    (n, 12), hess (n, 12, 12), zero where not given), the status per hinge and why: a hinge whose outputs hold
    a NaN or on which fn raises is missing, one with an infinity non-finite. `seconds`: the time inside fn.
    """

    def __init__(self, fn, names, batch):
        self.fn, self.names, self.batch = fn, names, batch
        self.seconds = 0.0
        self.notes = []

    def _call(self, args):
        t = time.perf_counter()
        try:
            return self.fn(*args)
        finally:
            self.seconds += time.perf_counter() - t

    def run(self, inputs, columns):
        names = self.names
        n = inputs[0].shape[0]
        got = {name: np.zeros((n, int(np.prod(_SHAPES[name][0])))) for name in names}
        status = np.full(n, _OK, dtype=np.int64)
        errors = [""] * n

        def store(rows, values):
            for name, v in values.items():
                got[name][rows] = v

        def one_by_one(shape_one):
            for i in range(n):
                try:
                    result = self._call(tuple(a[i].reshape(shape_one).copy() for a in inputs))
                except Exception as e:  # noqa: BLE001 (a raising candidate is graded, not propagated)
                    status[i], errors[i] = _MISSING, _describe(e)
                    continue
                store([i], _unpack(result, names, 1, len(shape_one) == 2))

        if n == 0:
            pass
        elif self.batch:
            try:
                result = self._call(tuple(a.copy() for a in inputs))
            except Exception as e:  # noqa: BLE001 (retried hinge by hinge to name the hinges that raise)
                one_by_one((1, 12))
                raised = int(np.count_nonzero(status == _MISSING))
                self.notes.append(
                    f"the batch call (n = {n}) raised: {_describe(e)[len('fn raised '):]}; retried one hinge at a time, "
                    + (f"{raised} hinge(s) raised" if raised else "no hinge raised alone: the failure is the batch's")
                )
            else:
                store(slice(None), _unpack(result, names, n, True))
        else:
            one_by_one((12,))

        # Back to the contract's order: the candidate's variable i is the contract's columns[i].
        value = got[names[0]][:, 0].copy() if names[0] in got else np.zeros(n)
        grad = np.zeros((n, 12))
        if "grad" in got:
            grad[:, columns] = got["grad"]
        hess = np.zeros((n, 12, 12))
        if "hess" in got:
            hess[:, columns[:, None], columns[None, :]] = got["hess"].reshape(n, 12, 12)
        given_values = np.concatenate([got[name] for name in names], axis=1)
        for i in np.flatnonzero(status == _OK):
            row = given_values[i]
            if np.isnan(row).any():
                status[i], errors[i] = _MISSING, "a NaN in the outputs"
            elif not np.isfinite(row).all():
                status[i], errors[i] = _NONFINITE, "an infinity in the outputs"
        return value, grad, hess, status, errors


def conform(
    fn,
    *,
    outputs=OUTPUTS,
    stencil=LABELS,
    dtype="float64",
    batch=True,
    depth="quick",
):
    """Grade a bending kernel against certified values, in its own conventions.

    fn(X): X a fresh C-contiguous (n, 12) array of dtype `dtype`, each row a hinge, its four vertices in
    the order `stencil` gives in the contract's labels (("x0", "x3", "x1", "x2") for a kernel whose hinge is
    opposite vertex, other opposite vertex, edge start, edge end). With batch=False, one hinge at a time,
    shape (12,). It returns a dict keyed by the names in `outputs`, or a tuple in that order: theta (n,),
    grad (n, 12), hess (n, 12, 12) or (n, 144), in its own variable order (vertex-major, its stencil), as
    any array numpy.asarray accepts. `outputs` may leave out "hess", or "grad" and "hess".

    dtype: "float64" (errors in units of 2^-53) or "float32" (the float32 set, outputs rounded to float,
    units of 2^-24). depth: "quick" (the nine categories) or "deep" (and at least 1000 hard hinges).

    A hinge whose outputs hold a NaN, or on which fn raises an Exception, is not evaluated (counted in
    `missing`); a batch that raises is retried hinge by hinge, shape (1, 12), to name the culprit.
    Returns a Report. Raises ValueError for a bad argument or an output of the wrong shape or dtype.
    """
    start = time.perf_counter()
    if not callable(fn):
        raise ValueError(f"fn must be callable; got {type(fn).__name__}")
    names = _outputs(outputs)
    order = _stencil_indices(stencil)
    dtype_name = _dtype(dtype)
    _choice(depth, "depth", ("quick", "deep"))
    if not isinstance(batch, (bool, np.bool_)):
        raise ValueError(f"batch= must be True or False; got {batch!r}")
    ids, _, x = _hinge.conformance_set(dtype_name, depth)
    n = len(ids)
    # The candidate's column i is the contract's column columns[i] (its vertex j is x_{order[j]}).
    columns = np.array([3 * order[j] + c for j in range(4) for c in range(3)])
    x_candidate = np.ascontiguousarray(x[:, columns], dtype=dtype_name)

    given = {name: name in names for name in OUTPUTS}
    calls = _Calls(fn, names, batch)
    theta, grad, hess, status, errors = calls.run((x_candidate,), columns)
    name = getattr(fn, "__qualname__", None) or type(fn).__name__
    compiled = _hinge.conformance_grade(
        f"Python function {name}",
        dtype_name,
        depth,
        [given[g] for g in OUTPUTS],
        order,
        theta,
        grad,
        hess.reshape(n, 144),
        status.tolist(),
        errors,
        calls.notes,
    )
    total = time.perf_counter() - start
    return Report(compiled, calls.seconds, total - calls.seconds)


def _weights(weight, rest_candidate):
    """(label, w): a named weight (w None: the kit computes it) or a callable's weights of the rest hinges."""
    if isinstance(weight, str):
        names = tuple(_hinge.energy_weight_names())
        if weight not in names:
            raise ValueError(f"weight= must be one of {', '.join(repr(n) for n in names)} or a callable; got {weight!r}")
        return weight, None
    if not callable(weight):
        raise ValueError(f"weight= must be a weight's name or a callable of the rest hinges; got {weight!r}")
    try:
        w = np.asarray(weight(rest_candidate.copy()), dtype=np.float64)
    except Exception as e:  # noqa: BLE001 (reported as the argument's fault)
        raise ValueError(f"weight(R) raised {type(e).__name__}: {e}") from None
    n = rest_candidate.shape[0]
    if w.shape != (n,):
        raise ValueError(f"weight(R) returned shape {w.shape} for n = {n} rest hinges; expected ({n},)")
    bad = np.flatnonzero(~(np.isfinite(w) & (w > 0)))
    if bad.size:
        raise ValueError(f"weight(R) returned {w[bad[0]]!r} for rest hinge {int(bad[0])}: weights must be finite and positive")
    return "callable", w


def conform_energy(
    fn,
    *,
    energy="tan",
    weight="contract",
    k=1.0,
    hessian="exact",
    blocks="full",
    outputs=ENERGY_OUTPUTS,
    stencil=LABELS,
    dtype="float64",
    depth="quick",
    batch=True,
):
    """Grade a bending term psi = k w f(theta, theta_bar) against certified values, in its own conventions.

    fn(X, R): X the deformed and R the rest hinges, both fresh C-contiguous (n, 12) arrays of dtype `dtype`,
    each row a hinge in the order `stencil` gives in the contract's labels. The term computes its own weights
    and rest angles from R, as a simulator does. It returns a dict keyed by the names in `outputs`, or a
    tuple in that order: energy (n,), grad (n, 12), hess (n, 12, 12) or (n, 144) of psi with respect to X, in
    its own variable order. With batch=False, one hinge at a time (X and R of shape (12,)).

    energy: "shells", "tan", "willmore", "bridson", "quadratic" (the isometric bending of Bergou et al.
    2006, on flat rest hinges, without weight; docs/quantities.md) or "custom" (the consistency checks
    only). weight: "contract" (3 |e_bar|^2 / A_bar), another name of docs/energy-conformance.md ("bridson",
    "edge-length", "unit"), or a callable of the rest hinges R (candidate order, (n, 12)) returning w (n,).
    hessian: "exact", "gauss-newton" (c f'' grad theta grad theta^T, not clamped) or "projected" (each hinge's
    exact Hessian with its negative eigenvalues set to zero: graded against a 256-bit evaluation, not
    certified, its tier at best "policy"). blocks: "full", or
    "diagonal" (only the Hessian's four 3 x 3 diagonal blocks graded, as vertex block descent uses them).

    Besides the certified values, the consistency checks run on the well-shaped hinges (gradient against
    differences of the energy, Hessian against differences of the gradient, symmetry, rigid motions, net
    force and torque); a failed check fails the run. Returns a Report (``settings``, ``checks`` besides the
    theta kit's). Raises ValueError for a bad argument or an output of the wrong shape or dtype, and for what
    this version does not grade yet: depth="deep" or hessian="projected" with dtype="float32". dtype="float32"
    grades on the float32 pairs (every coordinate a normal float), the term's outputs rounded to float, in
    units of 2^-24. depth="deep" adds 20 hinges of each hard family with
    every kind of rest hinge (about 900 pairs) whose condition numbers are computed at run time: about 15 ms
    a pair.
    """
    start = time.perf_counter()
    if not callable(fn):
        raise ValueError(f"fn must be callable; got {type(fn).__name__}")
    _choice(energy, "energy", ENERGIES)
    _choice(hessian, "hessian", ("exact", "gauss-newton", "projected"))
    _choice(blocks, "blocks", ("full", "diagonal"))
    dtype_name = _dtype(dtype)
    _choice(depth, "depth", ("quick", "deep"))
    if energy == "quadratic" and hessian != "exact":
        raise ValueError(f"hessian={hessian!r}: the quadratic energy's Hessian is constant, only 'exact' is graded")
    if energy == "quadratic" and not (isinstance(weight, str) and weight == "contract"):
        raise ValueError("weight=: the quadratic energy takes no weight (its 3 / A_bar is part of its definition)")
    not_yet = {
        "depth": dtype_name == "float32" and depth == "deep",
        "hessian": dtype_name == "float32" and hessian == "projected",
    }
    for name, missing in not_yet.items():
        if missing:
            value = {"depth": depth, "hessian": hessian}[name]
            raise ValueError(f"{name}={value!r} with dtype='float32' is not graded by this version of "
                             "hinge.conform_energy yet (docs/energy-conformance.md, \"Not yet\")")
    if isinstance(k, bool) or not isinstance(k, (int, float, np.floating, np.integer)) or not (0 < float(k) < math.inf):
        raise ValueError(f"k= must be a finite positive number; got {k!r}")
    if not isinstance(batch, (bool, np.bool_)):
        raise ValueError(f"batch= must be True or False; got {batch!r}")
    names = _outputs(outputs, ENERGY_OUTPUTS)
    order = _stencil_indices(stencil)
    columns = np.array([3 * order[j] + c for j in range(4) for c in range(3)])

    ids, _, x, rest, _ = _hinge.energy_set(energy, depth, dtype_name)
    n = len(ids)
    rest_candidate = np.ascontiguousarray(rest[:, columns], dtype=dtype_name)
    label, w = ("none", None) if energy == "quadratic" else _weights(weight, rest_candidate)
    calls = _Calls(fn, names, batch)
    values, grad, hess = np.zeros(n), np.zeros((n, 12)), np.zeros((n, 12, 12))
    status, errors = np.full(n, _OK, dtype=np.int64), [""] * n
    if energy != "custom":
        x_candidate = np.ascontiguousarray(x[:, columns], dtype=dtype_name)
        values, grad, hess, status, errors = calls.run((x_candidate, rest_candidate), columns)
    px, prest, _ = _hinge.consistency_probes(energy, dtype_name, depth)
    probes = tuple(np.ascontiguousarray(a[:, columns], dtype=dtype_name) for a in (px, prest))
    pvalues, pgrad, phess, pstatus, _ = calls.run(probes, columns)
    name = getattr(fn, "__qualname__", None) or type(fn).__name__
    compiled = _hinge.energy_grade(
        f"Python function {name}",
        energy,
        float(k),
        hessian,
        label,
        [] if w is None else w.tolist(),
        blocks == "diagonal",
        dtype_name,
        [g in names for g in ENERGY_OUTPUTS],
        order,
        values,
        grad,
        hess.reshape(n, 144),
        status.tolist(),
        errors,
        calls.notes,
        pvalues,
        pgrad,
        phess.reshape(len(pvalues), 144),
        (pstatus == _OK).tolist(),
        depth,
    )
    total = time.perf_counter() - start
    return Report(compiled, calls.seconds, total - calls.seconds)
