#!/usr/bin/python3
"""Generates symbolic_theta.inc: theta, its gradient and its Hessian as C++ that SymPy writes from the atan2
definition (docs/contract.md), with common-subexpression elimination. The `symbolic` method of the study.

    theta = atan2(((N x Nt) . e0) / |e0|, N . Nt),
    e0 = x2 - x1,  N = (x1 - x0) x (x2 - x0),  Nt = (x2 - x3) x (x1 - x3).

SymPy differentiates theta over the intermediate symbols u = (e0, N, Nt) (9 of them) and the chain rule
takes the result to the 12 coordinates: grad = J^T g_u and Hess = J^T H_u J + sum_k g_u[k] d2u_k/dx2, with
J = du/dx linear in the edge vectors a = x1 - x0, b = x2 - x0, c = x2 - x3, d = x1 - x3 and d2u_k/dx2
constant. Differentiating over the 12 coordinates directly gives the same values but expressions that cse
takes far longer to factor. Nothing is simplified or reordered by hand: the code is what sympy.cse and
the printer below give.

Usage: symbolic_theta.py OUT.inc (run with PYTHONHASHSEED=0: tests/baselines regenerates the committed
file and compares it byte for byte).
"""
import sys

import sympy as sp
from sympy.printing.c import C99CodePrinter


def vec(name):
    return sp.Matrix(sp.symbols(f"{name}x {name}y {name}z", real=True))


# Intermediate symbols the generated code computes from x first (subtractions and two cross products).
e0, N, Nt = vec("e0"), vec("N"), vec("Nt")
a, b, c, d = vec("a"), vec("b"), vec("c"), vec("d")
u = list(e0) + list(N) + list(Nt)

# theta as a function of u (the atan2 definition).
theta_u = sp.atan2(N.cross(Nt).dot(e0) / sp.sqrt(e0.dot(e0)), N.dot(Nt))
g_u = [sp.diff(theta_u, v) for v in u]
H_u = sp.Matrix(9, 9, lambda i, j: sp.diff(g_u[i], u[j]))

# u as a function of the coordinates x (12 symbols), and J = du/dx written with the edge vectors (e0 among them).
x = sp.Matrix(sp.symbols("X0:12", real=True))
X = [x[3 * i:3 * i + 3, 0] for i in range(4)]
u_of_x = list(X[2] - X[1]) + list((X[1] - X[0]).cross(X[2] - X[0])) + list((X[2] - X[3]).cross(X[1] - X[3]))
edges = {}
for sym, value in zip(list(a) + list(b) + list(c) + list(d) + list(e0),
                      list(X[1] - X[0]) + list(X[2] - X[0]) + list(X[2] - X[3]) + list(X[1] - X[3]) + list(X[2] - X[1])):
    edges[sym] = value
J = sp.Matrix(9, 12, lambda k, j: sp.diff(u_of_x[k], x[j]))
# J's entries are linear in x: rewrite each as an edge-vector component (they are all +- one of them, or constants).
by_value = {}
for sym, value in edges.items():
    by_value[sp.expand(value)] = sym
    by_value[sp.expand(-value)] = -sym


def in_edges(e):
    e = sp.expand(e)
    return e if e.is_number else by_value[e]


J = J.applyfunc(in_edges)
D2 = [sp.Matrix(12, 12, lambda i, j: sp.diff(u_of_x[k], x[i], x[j])) for k in range(9)]  # constants

grad = J.T * sp.Matrix(g_u)
hess = J.T * H_u * J
for k in range(9):
    if any(v != 0 for v in D2[k]):
        hess += g_u[k] * D2[k]


class ScalarPrinter(C99CodePrinter):
    """C++ for any scalar type S: sqrt unqualified (found by argument-dependent lookup for the multiprecision
    types), atan2 as theta_atan2 (symbolic_impl.hpp), integer powers as products, constants as S(n)."""

    def _print_Integer(self, e):
        return f"S({int(e)})"

    def _print_Rational(self, e):
        return f"(S({e.p}) / S({e.q}))"

    def _print_Pow(self, e):
        base, exp = e.base, e.exp
        b = self.parenthesize(base, sp.printing.precedence.PRECEDENCE["Mul"] + 1)
        if exp.is_Integer and exp > 0:
            return "(" + " * ".join([b] * int(exp)) + ")"
        if exp.is_Integer and exp < 0:
            return "(S(1) / " + self._print(sp.Pow(base, -exp, evaluate=False)) + ")"
        if exp == sp.Rational(1, 2):
            return f"sqrt({self._print(base)})"
        if exp == -sp.Rational(1, 2):
            return f"(S(1) / sqrt({self._print(base)}))"
        if exp.is_Rational and exp.q == 2:  # b^(n/2) = b^((n-1)/2) sqrt(b)
            whole = sp.Pow(base, (exp.p - 1) // 2 if exp > 0 else (exp.p + 1) // 2, evaluate=False)
            if exp > 0:
                return f"({self._print(whole)} * sqrt({self._print(base)}))"
            return f"(S(1) / ({self._print(sp.Pow(base, -(exp.p + 1) // 2, evaluate=False))} * sqrt({self._print(base)})))"
        raise ValueError(f"unexpected power {e}")

    def _print_Symbol(self, e):
        return e.name

    def _print_atan2(self, e):  # symbolic_impl.hpp's guard around the scalar type's atan2
        return f"theta_atan2({self._print(e.args[0])}, {self._print(e.args[1])})"


printer = ScalarPrinter()


def body(outputs, targets):
    """C++ statements: cse temporaries, then each target = its expression."""
    temps, reduced = sp.cse(outputs, symbols=sp.numbered_symbols("t"), order="canonical")
    lines = [f"  const S {t} = {printer.doprint(v)};" for t, v in temps]
    lines += [f"  {target} = {printer.doprint(v)};" for target, v in zip(targets, reduced)]
    return lines


def prelude():
    lines = []
    for name, (p, q) in (("a", (1, 0)), ("b", (2, 0)), ("c", (2, 3)), ("d", (1, 3)), ("e0", (2, 1))):
        for k, comp in enumerate("xyz"):
            lines.append(f"  const S {name}{comp} = x[{3 * p + k}] - x[{3 * q + k}];")
    for name, (p, q) in (("N", ("a", "b")), ("Nt", ("c", "d"))):  # cross products
        for k, comp in enumerate("xyz"):
            i, j = "xyz"[(k + 1) % 3], "xyz"[(k + 2) % 3]
            lines.append(f"  const S {name}{comp} = {p}{i} * {q}{j} - {p}{j} * {q}{i};")
    return lines


upper = [(i, j) for i in range(12) for j in range(i, 12)]
levels = [
    ("symbolic_theta", "S& theta", [theta_u], ["theta"]),
    ("symbolic_theta_gradient", "S& theta, S* grad", [theta_u] + list(grad), ["theta"] + [f"grad[{i}]" for i in range(12)]),
    ("symbolic_theta_hessian", "S& theta, S* grad, S* hess",
     [theta_u] + list(grad) + [hess[i, j] for i, j in upper],
     ["theta"] + [f"grad[{i}]" for i in range(12)] + [f"hess[{12 * i + j}]" for i, j in upper]),
]

out = [
    "// Generated by baselines/src/symbolic_theta.py (SymPy " + sp.__version__ + ", cse) from the atan2 definition of",
    "// theta (docs/contract.md); do not edit. x: the 12 coordinates x0.x .. x3.z in S; grad 12, hess 144",
    "// row-major (the upper triangle is generated, the lower mirrored). sqrt is called unqualified, atan2 as",
    "// theta_atan2 (symbolic_impl.hpp).",
    "// clang-format off",
]
for level, (name, args, outputs, targets) in enumerate(levels):
    out.append("")
    out.append("template <class S>")
    out.append(f"void {name}(const S* x, {args}) {{")
    out += prelude()
    out += body(outputs, targets)
    if level == 2:
        out.append("  for (int i = 0; i < 12; ++i)")
        out.append("    for (int j = 0; j < i; ++j) hess[12 * i + j] = hess[12 * j + i];")
    out.append("}")
out.append("// clang-format on")

with open(sys.argv[1], "w") as f:
    f.write("\n".join(out) + "\n")
