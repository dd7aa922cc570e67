#!/usr/bin/env bash
# The cloth-sphere scene (scenes/cloth-sphere.json) at 21^2, 41^2 and 81^2 vertices: each run for 10 steps
# (free fall, the cloth reaching the sphere's barrier), the matrix of step 10's first Newton iteration
# dumped (--dump-system 10:1), then CHOLMOD alone (supernodal and simplicial) and Eigen's LDL^T timed on
# the three matrices side by side by sim_solver_bench, beside the simulator's own linear solve per
# factorization in the same runs (summary.json: time_s.linear_solve / solver.factorizations).
# Usage: bench/sim_solvers.sh [BUILD_DIR (default build/bench)]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/bench}
work=$(mktemp -d /tmp/hinge-sim-solvers.XXXXXX)
trap 'rm -rf "$work"' EXIT
files=()
for n in 21 41 81; do
  /usr/bin/python3 - "$n" "$work/scene-$n.json" <<'PY'
import json, sys
n, path = int(sys.argv[1]), sys.argv[2]
s = json.load(open("scenes/cloth-sphere.json"))
s["mesh"]["grid"]["vertices"] = [n, n]
s["solve"]["steps"] = 10
json.dump(s, open(path, "w"))
PY
  "$build/tools/hinge" simulate "$work/scene-$n.json" --out "$work/n$n" --quiet --dump-system 10:1 >/dev/null
  files+=("$work/n$n/system/10-1.solved.mtx")
  /usr/bin/python3 -c "
import json, sys
s = json.load(open('$work/n$n/summary.json'))
f = s['solver']['factorizations']
print('simulator n = $n: %d unknowns, %s, %d factorizations, linear solve %.2f ms per factorization'
      % (3 * $n * $n, s['solver']['linear_solver'], f, 1e3 * s['time_s']['linear_solve'] / f))"
done
"$build/bench/sim_solver_bench" "${files[@]}" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
