#!/usr/bin/env bash
# What certification costs through the command: `hinge oracle` against `hinge eval --method fast` on the
# same file of hinges, both reading JSON Lines and writing their results, side by side in one run.
#
# The hinges: COUNT (default 8000) random hinges, 12 coordinates uniform in [-1, 1] (Python's random,
# seed 1). Each command runs five times, alternating; the medians of wall-clock and user CPU time, their
# ratio, and the paths the oracle took (--report-precision) are printed. Outputs go to /dev/shm.
#
# Usage: bench/oracle_vs_eval.sh [BUILD] [COUNT]   (BUILD: a build with the hinge tool, default build/release)
set -euo pipefail
BUILD=${1:-build/release}
COUNT=${2:-8000}
HINGE=$BUILD/tools/hinge
[[ -x $HINGE ]] || { echo "oracle_vs_eval: $HINGE is missing (build first)" >&2; exit 2; }
WORK=$(mktemp -d /dev/shm/hinge-oracle-XXXXXX)
trap 'rm -rf "$WORK"' EXIT

/usr/bin/python3 - "$COUNT" "$WORK/hinges.jsonl" <<'EOF'
import json, random, sys
random.seed(1)
with open(sys.argv[2], "w") as f:
    for i in range(int(sys.argv[1])):
        f.write(json.dumps({"id": i, "x": [random.uniform(-1, 1) for _ in range(12)]}) + "\n")
EOF

times() {  # "wall user" seconds of one command
  local TIMEFORMAT='%3R %3U'
  { time "$@" > /dev/null 2>&1; } 2>&1
}
median() { sort -g | sed -n 3p; }

oracle_runs="" eval_runs=""
for round in 1 2 3 4 5; do
  oracle_runs+="$(times "$HINGE" oracle --input "$WORK/hinges.jsonl" --output "$WORK/oracle.jsonl")"$'\n'
  eval_runs+="$(times "$HINGE" eval --method fast --input "$WORK/hinges.jsonl" --output "$WORK/eval.jsonl")"$'\n'
done
ow=$(awk '{print $1}' <<< "$oracle_runs" | median) ou=$(awk '{print $2}' <<< "$oracle_runs" | median)
ew=$(awk '{print $1}' <<< "$eval_runs" | median) eu=$(awk '{print $2}' <<< "$eval_runs" | median)
printf 'oracle_vs_eval: %d hinges, medians of five runs each\n' "$COUNT"
printf '%-36s %10s %10s\n' command "wall s" "user s"
printf '%-36s %10.3f %10.3f\n' "hinge oracle" "$ow" "$ou" "hinge eval --method fast" "$ew" "$eu"
printf '%-36s %10.2f %10.2f\n' "ratio oracle / eval" "$(echo "$ow / $ew" | bc -l)" "$(echo "$ou / $eu" | bc -l)"
printf 'per hinge: oracle %.1f us, eval %.1f us (wall)\n' "$(echo "1000000 * $ow / $COUNT" | bc -l)" \
       "$(echo "1000000 * $ew / $COUNT" | bc -l)"
printf 'paths:'
"$HINGE" oracle --report-precision --input "$WORK/hinges.jsonl" | grep -o '"path": "[a-z]*"' | sort | uniq -c |
  awk '{printf " %s %s", $3, $1} END {print ""}' | tr -d '"'
