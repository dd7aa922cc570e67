#!/usr/bin/env bash
# output-digests.sh BUILD_DIR: the sha256 of a fixed set of the command's outputs, one line each, under
# every instruction set this processor has (HINGE_ISA). Two builds whose listings are equal give the same
# bits: run it on the build before and after a change that must not change any output (a restructure)
# and compare with diff. What it runs: eval in six scalar types (reference and fast) on the conformance
# inputs, the oracle on them, hessian with tan and shells on a curved-rest mesh and the conformance meshes,
# oracle --mesh, and two shipped scenes (a static cantilever and a short cloth-sphere at 11 x 11).
set -euo pipefail
build=$(cd "${1:?usage: output-digests.sh BUILD_DIR}" && pwd)
hinge=$build/tools/hinge
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

"$hinge" conform --inputs >"$work/inputs.jsonl"
isas=(baseline)
grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo && isas+=(avx2)
grep -qw avx512f /proc/cpuinfo && isas+=(avx512)
crumple=$root/scenes/meshes/crumple.obj
crumple_rest=$root/scenes/meshes/crumple-rest.obj
hex=$root/conformance/meshes/hex.obj
hex_rest=$root/conformance/meshes/hex-rest.obj
python3 - "$root/scenes/cloth-sphere.json" "$work/cloth-sphere-11.json" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
s["mesh"]["grid"]["vertices"] = [11, 11]
s["solve"]["steps"] = 30
json.dump(s, open(sys.argv[2], "w"))
EOF
sed "s|\"meshes/|\"$root/scenes/meshes/|" "$root/scenes/cantilever.json" >"$work/cantilever.json"

digest() { printf '%s %s\n' "$(sha256sum "$2" | cut -c1-64)" "$1"; }
for isa in "${isas[@]}"; do
  export HINGE_ISA=$isa
  o=$work/$isa
  mkdir -p "$o"
  for method in reference fast; do
    for scalar in float double long-double float128 bin128 mpfr:200; do
      "$hinge" eval --method $method --scalar $scalar <"$work/inputs.jsonl" >"$o/eval"
      digest "$isa eval $method $scalar" "$o/eval"
    done
  done
  "$hinge" oracle <"$work/inputs.jsonl" >"$o/oracle"
  digest "$isa oracle" "$o/oracle"
  for energy in tan shells; do
    for method in fast reference; do
      "$hinge" hessian --mesh "$crumple" --rest "$crumple_rest" --energy $energy --k 1 --method $method \
        --out "$o/h.mtx" --gradient "$o/g.txt" >"$o/e.txt"
      digest "$isa hessian crumple $energy $method H" "$o/h.mtx"
      digest "$isa hessian crumple $energy $method G" "$o/g.txt"
      digest "$isa hessian crumple $energy $method E" "$o/e.txt"
    done
    "$hinge" hessian --mesh "$hex" --rest "$hex_rest" --energy $energy --young 1e6 --poisson 0.3 \
      --thickness 0.01 --out "$o/h.mtx" --gradient "$o/g.txt" >"$o/e.txt"
    digest "$isa hessian hex $energy H" "$o/h.mtx"
    digest "$isa hessian hex $energy G+E" <(cat "$o/g.txt" "$o/e.txt")
    "$hinge" oracle --mesh "$hex" --rest "$hex_rest" --energy $energy --k 1 --out "$o/h.mtx" \
      --gradient "$o/g.txt" >"$o/e.txt"
    digest "$isa oracle-mesh hex $energy H+G+E" <(cat "$o/h.mtx" "$o/g.txt" "$o/e.txt")
  done
  "$hinge" hessian --mesh "$crumple" --rest "$crumple_rest" --energy willmore --k 1 --scalar long-double \
    --method reference --out "$o/h.mtx" >"$o/e.txt"
  digest "$isa hessian crumple willmore long-double H+E" <(cat "$o/h.mtx" "$o/e.txt")
  for scene in cantilever cloth-sphere-11; do
    "$hinge" simulate "$work/$scene.json" --out "$o/$scene" --quiet >/dev/null
    digest "$isa simulate $scene final" "$o/$scene/final.obj"
    if [ -d "$o/$scene/frames" ]; then
      digest "$isa simulate $scene frames" <(cat "$o/$scene"/frames/*.obj)
    fi
  done
done
