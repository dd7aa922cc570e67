#!/usr/bin/env python3
"""Checks docs/paper-map.md against the code (ctest docs.paper_map).

Usage: test_paper_map.py REPO_ROOT [MAP]   (MAP defaults to REPO_ROOT/docs/paper-map.md)

Plain Python 3, standard library only. Prints what it checks; exits 0 when everything holds, 1 when
something does not (each failure printed), 2 on a usage error.

(a) Every equation tag the code cites ("eq. (N)", "Eq. (N)", "eqs. (4)-(6)", "eqs. (4) and (6)",
    "Equation (N)") is in the map: a table row whose first cell is "eq. (N)", or a heading naming
    "eq. (N)". Scanned: C++ (.cpp .hpp .h .c .inc, and .in templates) under the library and program
    folders, and every .py file of the repository (generators, scripts, checks, tests). The map must
    also cover every equation the paper numbers, (1)-(12).
(b) Every path the map names in backticks (a span with a '/' and a file extension) exists, relative to
    the repository root; names given in backticks in parentheses right after a path
    (`path` (`function`, `Class::member`)) occur in that file.
(c) Every Algorithm line the code cites ("Algorithm 1, line 2", "Alg. 2, line 9", "lines 8-11" in a file
    that names Algorithm 2) has a row "Algorithm K, line N" in the map; line numbers beyond the
    algorithm's last line are reported as wrong citations.
(d) Every erratum the code cites ("erratum 1", "erratum E5", "E3:" in a file that mentions errata), and
    every erratum heading of proofs/errata.md, has a row in the map's errata table.
"""
import os
import re
import sys

PAPER_EQUATIONS = range(1, 13)  # the paper numbers its equations (1)-(12)
ALGORITHM_LINES = {1: 5, 2: 21}  # Algorithm 1 has 5 lines, Algorithm 2 has 21
CXX_DIRS = ["core", "reference", "fast", "oracle", "conformance", "baselines", "methods", "sim", "study",
            "io", "tools", "python", "bench"]
CXX_EXT = (".cpp", ".hpp", ".h", ".c", ".inc", ".in")
SKIP_DIRS = {".git", "build", "__pycache__"}

EQ_TAG = re.compile(r"\b(?:[Ee]qs?\.|[Ee]quations?)\s*\((\d+)\)((?:\s*(?:-|–|and|,|or)\s*\(\d+\))*)")
EQ_MORE = re.compile(r"(-|–|and|,|or)\s*\((\d+)\)")
ALG_LINE = re.compile(r"\b(?:Algorithm|Alg\.)\s*([12])\s*,?\s*lines?\s+(\d+)(?:\s*-\s*(\d+))?")
BARE_LINE = re.compile(r"\blines?\s+(\d+)(?:\s*-\s*(\d+))?\b", re.IGNORECASE)
ERRATUM = re.compile(r"\berrat(?:um|a)\s+E?([1-9])\b")
E_TAG = re.compile(r"\bE([1-9])\b")


def relative(root, path):
    return os.path.relpath(path, root)


def code_files(root):
    """The files whose comments are scanned: C++ in CXX_DIRS, every .py outside build/ and .git/ (but
    this script, whose documentation quotes citations)."""
    seen = set()
    for d in CXX_DIRS:
        for base, dirs, files in os.walk(os.path.join(root, d)):
            dirs[:] = sorted(x for x in dirs if x not in SKIP_DIRS)
            for f in sorted(files):
                if f.endswith(CXX_EXT):
                    seen.add(os.path.join(base, f))
    for base, dirs, files in os.walk(root):
        dirs[:] = sorted(x for x in dirs if x not in SKIP_DIRS)
        for f in sorted(files):
            if f.endswith(".py"):
                seen.add(os.path.join(base, f))
    seen.discard(os.path.join(root, "tests", "docs", os.path.basename(__file__)))
    return sorted(seen)


def equations_in(text):
    """Equation numbers cited in text, ranges expanded: eqs. (4)-(6) -> 4, 5, 6."""
    found = set()
    for m in EQ_TAG.finditer(text):
        last = int(m.group(1))
        found.add(last)
        for sep, num in EQ_MORE.findall(m.group(2)):
            n = int(num)
            if sep in ("-", "–") and last < n <= last + 12:
                found.update(range(last + 1, n + 1))
            found.add(n)
            last = n
    return found


def line_number(text, pos):
    return text.count("\n", 0, pos) + 1


def algorithm_lines_in(text, ambiguous=None):
    """(algorithm, line, position) cited in text. Explicit citations name the algorithm; a bare "line N"
    or "lines N-M" in a comment counts for Algorithm 2 in a file that names Algorithm 2 (hinge::fast's
    passes cite its lines that way). A bare citation in a file that names only Algorithm 1 is ambiguous:
    its position is appended to `ambiguous` (a note, not a failure)."""
    cited = []
    explicit = set()
    for m in ALG_LINE.finditer(text):
        a, lo = int(m.group(1)), int(m.group(2))
        hi = int(m.group(3)) if m.group(3) else lo
        cited.extend((a, n, m.start()) for n in range(lo, hi + 1))
        explicit.add(m.start(2))
    names_2 = re.search(r"\b(?:Algorithm|Alg\.)\s*2\b", text) is not None
    names_1 = re.search(r"\b(?:Algorithm|Alg\.)\s*1\b", text) is not None
    if not (names_1 or names_2):
        return cited
    for m in BARE_LINE.finditer(text):
        if m.start(1) in explicit:
            continue
        start = text.rfind("\n", 0, m.start()) + 1
        prefix = text[start:m.start()]
        if "//" not in prefix and not prefix.lstrip().startswith(("#", "*", "/*")):
            continue  # not a comment
        if not names_2:
            if ambiguous is not None:
                ambiguous.append(m.start())
            continue
        lo = int(m.group(1))
        hi = int(m.group(2)) if m.group(2) else lo
        cited.extend((2, n, m.start()) for n in range(lo, hi + 1))
    return cited


def errata_in(text):
    found = {int(n) for n in ERRATUM.findall(text)}
    if re.search(r"errat", text, re.IGNORECASE):
        found.update(int(n) for n in E_TAG.findall(text))
    return found


def table_rows(text):
    """Cells of every Markdown table row (header and separator rows included)."""
    rows = []
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("|") and s.endswith("|") and len(s) > 1:
            rows.append([c.strip() for c in s[1:-1].split("|")])
    return rows


def map_equations(text):
    found = set()
    for cells in table_rows(text):
        m = re.fullmatch(r"eq\.\s*\((\d+)\)", cells[0])
        if m:
            found.add(int(m.group(1)))
    for line in text.splitlines():
        if line.startswith("#"):
            found.update(int(n) for n in re.findall(r"eq\.\s*\((\d+)\)", line))
    return found


def map_algorithm_lines(text):
    found = set()
    for cells in table_rows(text):
        m = re.fullmatch(r"Algorithm\s+([12]),\s*line\s+(\d+)", cells[0])
        if m:
            found.add((int(m.group(1)), int(m.group(2))))
    return found


def map_errata(text):
    found = set()
    for cells in table_rows(text):
        m = re.fullmatch(r"E([1-9])", cells[0])
        if m:
            found.add(int(m.group(1)))
    return found


PATH_SPAN = re.compile(r"`([^`\s]+)`(\s*\(((?:[^()`]|`[^`]*`)*)\))?")


def looks_like_path(span):
    return "/" in span and re.search(r"\.[A-Za-z0-9]+$", span.rsplit("/", 1)[-1]) is not None


def identifier(name):
    """The identifier to look for in a file: the last part of a qualified name, without arguments."""
    name = name.split("(")[0].split("<")[0].strip()
    if name.startswith("--"):
        return name  # a command-line option, looked up as written
    return name.split("::")[-1]


def check_paths(root, text, failures):
    paths = functions = 0
    for lineno, line in enumerate(text.splitlines(), 1):
        for m in PATH_SPAN.finditer(line):
            span = m.group(1)
            if not looks_like_path(span):
                continue
            paths += 1
            full = os.path.join(root, span)
            if not os.path.isfile(full):
                failures.append(f"map line {lineno}: `{span}` does not exist")
                continue
            if m.group(3) is None:
                continue
            names = re.findall(r"`([^`]+)`", m.group(3))
            if not names:
                continue
            with open(full, encoding="utf-8", errors="replace") as f:
                body = f.read()
            for name in names:
                ident = identifier(name)
                if not ident or looks_like_path(name):
                    continue
                functions += 1
                pattern = re.escape(ident) if ident.startswith("--") else r"\b" + re.escape(ident) + r"\b"
                if not re.search(pattern, body):
                    failures.append(f"map line {lineno}: `{name}` does not occur in `{span}`")
    return paths, functions


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__)
        return 2
    root = os.path.abspath(argv[1])
    map_path = argv[2] if len(argv) == 3 else os.path.join(root, "docs", "paper-map.md")
    if not os.path.isfile(map_path):
        print(f"FAIL: no map at {map_path}")
        return 1
    with open(map_path, encoding="utf-8") as f:
        text = f.read()
    failures = []

    # (a) equation tags
    eq_in_map = map_equations(text)
    cited = {}  # equation -> first place it is cited
    files = code_files(root)
    alg_cited = {}
    errata_cited = {}
    notes = []
    for path in files:
        with open(path, encoding="utf-8", errors="replace") as f:
            body = f.read()
        rel = relative(root, path)
        for n in equations_in(body):
            cited.setdefault(n, rel)
        ambiguous = []
        for a, n, pos in algorithm_lines_in(body, ambiguous):
            alg_cited.setdefault((a, n), f"{rel}:{line_number(body, pos)}")
        notes.extend(f"{rel}:{line_number(body, pos)}" for pos in ambiguous)
        for n in errata_in(body):
            errata_cited.setdefault(n, rel)
    print(f"(a) {len(files)} files scanned; equations cited in the code: "
          f"{', '.join(f'({n})' for n in sorted(cited))}; in the map: {', '.join(f'({n})' for n in sorted(eq_in_map))}")
    for n in sorted(cited):
        if n not in eq_in_map:
            failures.append(f"eq. ({n}) is cited in {cited[n]} but not in the map")
    for n in PAPER_EQUATIONS:
        if n not in eq_in_map:
            failures.append(f"eq. ({n}) of the paper is not in the map")
    for n in sorted(set(eq_in_map) - set(PAPER_EQUATIONS)):
        failures.append(f"the map lists eq. ({n}), which the paper does not number")
    for n in sorted(set(cited) - set(PAPER_EQUATIONS)):
        failures.append(f"eq. ({n}) cited in {cited[n]}: the paper has no such equation")

    # (b) paths and the names beside them
    paths, functions = check_paths(root, text, failures)
    print(f"(b) {paths} paths named in the map, {functions} functions or members looked up in them")

    # (c) Algorithm lines
    alg_in_map = map_algorithm_lines(text)
    print(f"(c) Algorithm lines cited in the code: "
          f"{', '.join(f'{a}.{n}' for a, n in sorted(alg_cited))}; rows in the map: {len(alg_in_map)}")
    for where in notes:
        print(f"    note: {where} cites a bare line of an algorithm in a file that names only Algorithm 1")
    for (a, n), where in sorted(alg_cited.items()):
        if n < 1 or n > ALGORITHM_LINES[a]:
            failures.append(f"{where} cites Algorithm {a}, line {n}: Algorithm {a} has {ALGORITHM_LINES[a]} lines")
        elif (a, n) not in alg_in_map:
            failures.append(f"Algorithm {a}, line {n} is cited in {where} but has no row in the map")
    for a, last in ALGORITHM_LINES.items():
        for n in range(1, last + 1):
            if (a, n) not in alg_in_map:
                failures.append(f"Algorithm {a}, line {n} has no row in the map")

    # (d) errata
    errata_file = os.path.join(root, "proofs", "errata.md")
    listed = set()
    if os.path.isfile(errata_file):
        with open(errata_file, encoding="utf-8") as f:
            listed = {int(n) for n in re.findall(r"^##\s+E(\d+)\b", f.read(), re.MULTILINE)}
    errata_map = map_errata(text)
    print(f"(d) errata cited in the code: {', '.join(f'E{n}' for n in sorted(errata_cited))}; "
          f"in proofs/errata.md: {', '.join(f'E{n}' for n in sorted(listed))}; "
          f"in the map: {', '.join(f'E{n}' for n in sorted(errata_map))}")
    for n, where in sorted(errata_cited.items()):
        if n not in errata_map:
            failures.append(f"erratum E{n} is cited in {where} but has no row in the map")
    for n in sorted(listed - errata_map):
        failures.append(f"erratum E{n} of proofs/errata.md has no row in the map")

    if failures:
        for f in failures:
            print("FAIL:", f)
        print(f"{len(failures)} failure(s)")
        return 1
    print("OK: the map covers every equation, Algorithm line and erratum the code cites, and its paths exist")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
