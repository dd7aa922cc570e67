#!/usr/bin/env bash
# The README's first command: installs the dependencies, builds the release configuration and runs the
# main job on its built-in defaults (hinge demo: the quick study, written to build/study, and the fast
# kernel's conformance verdict), then checks a small NumPy kernel from Python (scripts/demo-conform.py: written
# in another stencil order with its angle negated; the report's diagnosis says what to change).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target hinge hinge_python
./build/release/tools/hinge demo --out build/study "$@"
echo
echo "== a NumPy kernel checked from Python: hinge.conform (docs/python-conformance.md)"
PYTHONPATH=build/release/python /usr/bin/python3 scripts/demo-conform.py
