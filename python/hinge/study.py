"""What accuracy costs, with your own kernels on the chart (docs/study.md, "Your own kernel").

``study(candidates={"label": fn})`` runs the study of ``hinge study`` (every method in every scalar type,
the faithful mode and the certified oracle, timed by one method and measured against the certified
oracle) with each callable as an outside row: its errors measured on the study's hinges as ``hinge.conform``
calls it (the same callables, stencils and output forms), its time per hinge that of one call on the whole
batch of timing hinges, round by round beside fast in double in this process. Returns study.json's content.
"""

import json
import os
import time

import numpy as np

from . import _hinge
from .conformance import LABELS, OUTPUTS, _Calls, _outputs, _stencil_indices

__all__ = ["study"]


def _candidate(label, fn, names, order):
    """(label, evaluate, time) for the compiled study: evaluate(X) in the contract's order, time(X) in seconds."""
    columns = np.array([3 * order[j] + c for j in range(4) for c in range(3)])

    def evaluate(x):
        calls = _Calls(fn, names, True)
        theta, grad, hess, status, errors = calls.run((np.ascontiguousarray(x[:, columns]),), columns)
        return theta, grad, hess.reshape(len(theta), 144), status.tolist(), errors

    def timed(x):
        xc = np.ascontiguousarray(x[:, columns])
        start = time.perf_counter()
        fn(xc)
        return time.perf_counter() - start

    return (label, evaluate, timed)


def study(candidates=None, *, quick=True, out=None, methods=None, scalars=None, mesh=True, budget=None,
          outputs=OUTPUTS, stencil=LABELS):
    """The study, with callables as outside rows; study.json's content as a dict.

    candidates: {"label": fn}, each fn as hinge.conform takes it (batched: fn(X), X (n, 12) float64 in the
    vertex order `stencil` gives, returning theta, grad and hess as a dict or a tuple in the order of
    `outputs`, in its own variable order). Its row is "method": label, "outside": true; its three times are
    the one call's, per hinge over its batches. A batch that raises while timed leaves the row without a
    time and says why ("error"). quick: the quick study (about 20 s) or the full one (about 15 minutes).
    methods, scalars: the project's rows (default: all; names as ``hinge study --methods/--scalars``;
    ["fast"], ["double"] for the least beside the candidates). mesh: the mesh level. budget: seconds per row (default 1.5 quick,
    20 full). out: a folder to write study.json and study.md into (plots: ``hinge study``'s plot_study.py on
    that study.json). Raises ValueError for a bad argument.
    """
    candidates = {} if candidates is None else candidates
    if not isinstance(candidates, dict) or not all(isinstance(k, str) and callable(v) for k, v in candidates.items()):
        raise ValueError("candidates must be a dict of labels to callables")
    names = _outputs(outputs)
    if names != OUTPUTS:
        raise ValueError("study: a candidate gives theta, grad and hess (outputs must be all three)")
    order = _stencil_indices(stencil)
    rows = [_candidate(label, fn, names, order) for label, fn in candidates.items()]
    for name, value in (("methods", methods), ("scalars", scalars)):
        if value is not None and (isinstance(value, str) or not list(value)):
            raise ValueError(f"{name} must be a non-empty list of names, or None for all; got {value!r}")
    text, markdown = _hinge.study(bool(quick), float(budget or 0), list(methods) if methods is not None else [],
                                  list(scalars) if scalars is not None else [], bool(mesh), rows)
    if out is not None:
        os.makedirs(out, exist_ok=True)
        with open(os.path.join(out, "study.json"), "w") as f:
            f.write(text)
        with open(os.path.join(out, "study.md"), "w") as f:
            f.write(markdown)
    return json.loads(text)
