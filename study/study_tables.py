#!/usr/bin/python3
"""The tables of docs/study.md, made from a study.json (`hinge study`; docs/study.md), so that the page says
what the committed run measured and nothing copied by hand.

  study_tables.py STUDY.json                    print every table
  study_tables.py STUDY.json --update PAGE.md   replace each table of PAGE.md between its markers
  study_tables.py STUDY.json --check PAGE.md    exit 1 when PAGE.md's tables are not what STUDY.json makes
  study_tables.py STUDY.json --reduce OUT.json  write STUDY.json without the per-hinge arrays (hess_errors_u)

A table sits in the page between `<!-- table: NAME -->` and `<!-- end table -->`; NAME one of TABLES.
"""
import json
import re
import sys

GROUPS = ["theta", "grad", "hess"]
GROUP_NAMES = {"theta": "theta", "grad": "gradient", "hess": "Hessian"}


def units(v):
    """An error in units of 2^-53 with 2 significant digits, as study.md prints it."""
    if v == 0:
        return "0"
    if v >= 1e4:
        return f"{v:.1e}"
    if v >= 10:
        return f"{v:.0f}"
    return f"{v:.2g}"


def ratio(v):
    return f"{v:.2f}" if v < 10 else f"{v:.1f}" if v < 100 else f"{v:.0f}"


def ns(v):
    return f"{v:.2f}" if v < 10 else f"{v:.1f}" if v < 100 else f"{v:.0f}"


def label(r):
    return r["method"] + " (outside)" if r.get("outside") else f"{r['method']}/{r['scalar']}"


def worst(r):
    return max((g["max"] for e in r["error_u"].values() for g in e.values()), default=0)


def worst_group(r, category):
    """The worst error of any output in a category, and which output it is."""
    e = r["error_u"].get(category)
    if not e:
        return None, None
    g = max(GROUPS, key=lambda k: e[k]["max"])
    return e[g]["max"], g


def time_cell(r, ghz):
    t = r["ns_per_hinge"].get("hess")
    if not t:
        return "-"
    return f"{ns(t)} ({t * ghz:.0f})"


def not_evaluated(r):
    n = r["failed"] + r["nonfinite"]
    return str(n)


def table_run(s):
    m = s["machine"]
    kind = "quick" if s["quick"] else "full"
    return (f"{kind.capitalize()} study: {m['cpu']}, clock measured at {m['clock_ghz']:.2f} GHz; "
            f"{s['inputs']['hinges']} hinges ({s['inputs']['source']}) in {len(s['inputs']['categories'])} "
            f"categories; {len(s['rows'])} rows; {s['seconds']:.0f} s; build {s['build'].get('version', '?')} "
            f"({s['build'].get('commit', '?')}).\n")


def table_frontier(s):
    ghz = s["machine"]["clock_ghz"]
    rows = sorted((r for r in s["rows"] if r["on_frontier"]), key=lambda r: r["x_fast"]["hess"])
    out = ["| point | ns per hinge (cycles) | x fast | worst error, any output (u) |", "|---|---:|---:|---:|"]
    for r in rows:
        out.append(f"| {label(r)} | {time_cell(r, ghz)} | {ratio(r['x_fast']['hess'])} | {units(worst(r))} |")
    return "\n".join(out) + "\n"


def table_double(s):
    ghz = s["machine"]["clock_ghz"]
    typical = "well-shaped" if "well-shaped" in s["inputs"]["categories"] else s["inputs"]["categories"][0]
    rows = sorted((r for r in s["rows"] if r["scalar"] == "double" and r.get("x_fast")),
                  key=lambda r: r["x_fast"]["hess"])
    out = [f"| method | theta, gradient, Hessian: ns (cycles) | x fast | worst error, any output (u) | "
           f"worst Hessian error (u) | {typical} median, Hessian (u) | not evaluated | frontier |",
           "|---|---:|---:|---:|---:|---:|---:|:-:|"]
    for r in rows:
        med = r["error_u"].get(typical, {}).get("hess", {}).get("median")
        out.append(f"| {label(r)} | {time_cell(r, ghz)} | {ratio(r['x_fast']['hess'])} | {units(worst(r))} | "
                   f"{units(r['worst_hess_u'])} | {'-' if med is None else units(med)} | {not_evaluated(r)} | "
                   f"{'yes' if r['on_frontier'] else ''} |")
    return "\n".join(out) + "\n"


def table_categories(s):
    cats = s["inputs"]["categories"]
    rows = [r for r in s["rows"] if r["scalar"] == "double"]
    out = ["| method | " + " | ".join(cats) + " |", "|---|" + "---:|" * len(cats)]
    for r in rows:
        cells = []
        for c in cats:
            v, g = worst_group(r, c)
            cells.append("-" if v is None else units(v) if g == "hess" or v == 0 else f"{units(v)} ({GROUP_NAMES[g]})")
        out.append(f"| {label(r)} | " + " | ".join(cells) + " |")
    return "\n".join(out) + "\n"


def table_types(s):
    """Every row in every type: x fast and worst error, the frontier marked."""
    out = ["| method/scalar | x fast | worst error, any output (u) | worst own Hessian error (u of the type) | "
           "not evaluated | frontier |", "|---|---:|---:|---:|---:|:-:|"]
    for r in s["rows"]:
        own = max((e["hess"]["max"] for e in r.get("error_own", {}).values()), default=None)
        x = r.get("x_fast", {}).get("hess")
        out.append(f"| {label(r)} | {'-' if not x else ratio(x)} | {units(worst(r))} | "
                   f"{'-' if own is None else units(own)} | {not_evaluated(r)} | {'yes' if r['on_frontier'] else ''} |")
    return "\n".join(out) + "\n"


def table_escalation(s):
    out = ["| row | " + " | ".join(s["inputs"]["categories"]) + " |", "|---|" + "---:|" * len(s["inputs"]["categories"])]
    for r in s["rows"]:
        if "escalation" in r:
            out.append(f"| {label(r)} | " + " | ".join(
                f"{100 * r['escalation'][c]:.0f}%" if c in r["escalation"] else "-" for c in s["inputs"]["categories"]) + " |")
    return "\n".join(out) + "\n"


def table_mesh(s):
    f = s.get("mesh_shared_k")
    if not f:
        return "(no mesh level in this run)\n"
    out = [f"| method | ln a (k = {f['k']:.3f}) | fast's speedup |", "|---|---:|---:|"]
    for m, ln_a in f["ln_a"].items():
        out.append(f"| {m} | {ln_a:.3f} | {f.get('fast_speedup', {}).get(m, float('nan')):.2f} |")
    per_edge = ["", "| method | scalar | ns per interior edge, smallest .. largest size | k |", "|---|---|---:|---:|"]
    for m in s["mesh"]:
        if m["scalar"] == "double" and m["ns_per_edge"]:
            per_edge.append(f"| {m['method']} | double | {ns(min(m['ns_per_edge']))} .. {ns(max(m['ns_per_edge']))} "
                            f"({int(round(m['vertices'][0] ** 0.5))}^2 .. {int(round(m['vertices'][-1] ** 0.5))}^2) | "
                            f"{m['k']:.3f} |" if "k" in m else f"| {m['method']} | double | {ns(m['ns_per_edge'][0])} | - |")
    return "\n".join(out + per_edge) + "\n"


TABLES = {
    "run": table_run,
    "frontier": table_frontier,
    "double": table_double,
    "categories": table_categories,
    "types": table_types,
    "escalation": table_escalation,
    "mesh": table_mesh,
}

MARKER = re.compile(r"(<!-- table: ([a-z]+) -->\n)(.*?)(<!-- end table -->)", re.S)


def updated(page, study):
    def replace(m):
        name = m.group(2)
        if name not in TABLES:
            sys.exit(f"study_tables.py: unknown table '{name}' (known: {', '.join(TABLES)})")
        return m.group(1) + TABLES[name](study) + m.group(4)

    return MARKER.sub(replace, page)


def reduced(study):
    s = json.loads(json.dumps(study))
    for r in s["rows"]:
        r.pop("hess_errors_u", None)
    return s


def main(argv):
    if len(argv) not in (2, 4) or (len(argv) == 4 and argv[2] not in ("--update", "--check", "--reduce")):
        sys.exit(__doc__)
    with open(argv[1]) as f:
        study = json.load(f)
    if len(argv) == 2:
        for name, make in TABLES.items():
            print(f"<!-- table: {name} -->\n{make(study)}<!-- end table -->\n")
        return 0
    option, path = argv[2], argv[3]
    if option == "--reduce":
        with open(path, "w") as f:
            json.dump(reduced(study), f, indent=1)
            f.write("\n")
        return 0
    with open(path) as f:
        page = f.read()
    if not MARKER.search(page):
        sys.exit(f"study_tables.py: {path} has no table markers")
    new = updated(page, study)
    if option == "--update":
        with open(path, "w") as f:
            f.write(new)
        return 0
    if new != page:
        print(f"study_tables.py: the tables of {path} are not what {argv[1]} makes; run "
              f"study/study_tables.py {argv[1]} --update {path}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
