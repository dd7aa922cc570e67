#!/usr/bin/env bash
# What one evaluation costs through the command, `hinge hessian --method fast --threads 1 --repeat R`, against
# the library benchmark (mesh/fast/n:N/threads:1) at the same sizes, per interior edge, in one run.
#
# The command's cost per evaluation is the difference between a run with R evaluations and one with 1,
# over R - 1, in user CPU time: reading the OBJ files, Algorithm 1, the pattern and writing the outputs
# cancel. Outputs go to /dev/shm (no disk write-back in the next run). The median of three differences.
#
# Usage: bench/command_vs_library.sh [BUILD]   (BUILD: a bench build, default build/bench; it needs the
#        targets hinge, hinge_bench and cloth_obj: cmake --preset bench && cmake --build --preset bench)
set -euo pipefail
BUILD=${1:-build/bench}
HINGE=$BUILD/tools/hinge BENCH=$BUILD/bench/hinge_bench CLOTH=$BUILD/bench/cloth_obj
for f in "$HINGE" "$BENCH" "$CLOTH"; do [[ -x $f ]] || { echo "command_vs_library: $f is missing (build the bench preset)" >&2; exit 2; }; done
WORK=$(mktemp -d /dev/shm/hinge-command-XXXXXX)
trap 'rm -rf "$WORK"' EXIT

seconds() {  # user CPU seconds of one command (bash's time; the evaluations make no system call and, after
  local TIMEFORMAT=%3U  # the first, no page fault: the system time is the output's writing, whose noise
  { time "$@" > /dev/null 2>&1; } 2>&1  # at 1001^2 (2 GB into tmpfs) would swamp a wall-clock difference)
}

declare -A command_ns
for n in 101 1001; do
  "$CLOTH" "$n" 1 "$WORK/rest.obj"
  "$CLOTH" "$n" 2 "$WORK/deformed.obj"
  repeat=$([[ $n == 101 ]] && echo 401 || echo 41)
  edges=$(( 3 * (n - 1) * (n - 1) - 2 * (n - 1) ))
  run() { seconds "$HINGE" hessian --mesh "$WORK/deformed.obj" --rest "$WORK/rest.obj" --energy tan --k 1 \
                  --method fast --threads 1 --repeat "$1" --out "$WORK/H.mtx" --gradient "$WORK/g.txt"; }
  best=""
  for round in 1 2 3; do  # the median of three differences
    one=$(run 1) many=$(run "$repeat")
    best+="$(echo "1000000000 * ($many - $one) / ($repeat - 1) / $edges" | bc -l)"$'\n'
  done
  command_ns[$n]=$(printf '%s' "$best" | sort -g | sed -n 2p)
  printf 'command_vs_library: hinge hessian, %d^2: %.1f ns per interior edge per evaluation (%s evaluations)\n' \
         "$n" "${command_ns[$n]}" "$repeat" >&2
  rm -f "$WORK"/*.obj "$WORK/H.mtx" "$WORK/g.txt"
done

summary=$(HINGE_BENCH_MAX=1001 "$BENCH" --benchmark_filter='mesh/fast/n:(101|1001)/threads:1/' 2>/dev/null |
          sed -n '/== summary/,$p')
library() { awk -v n="$1" '$1 == n && NF >= 5 { print $4 }' <<< "$summary"; }
printf '%s\n' "$summary" | grep -E '^clock' || true
printf '%6s %22s %22s %8s\n' side "command ns/edge" "library ns/edge" ratio
for n in 101 1001; do
  lib=$(library "$n")
  printf '%6d %22.1f %22.1f %8.3f\n' "$n" "${command_ns[$n]}" "$lib" "$(echo "${command_ns[$n]} / $lib" | bc -l)"
done
printf 'command, 1001^2 against 101^2 per edge: %.3f\n' "$(echo "${command_ns[1001]} / ${command_ns[101]}" | bc -l)"
