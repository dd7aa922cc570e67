#!/usr/bin/env bash
# The README's first command: installs the dependencies, builds the release configuration and runs the
# main job on its built-in defaults (hinge demo: the quick study, written to build/study, and the fast
# kernel's conformance verdict).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target hinge
./build/release/tools/hinge demo --out build/study "$@"
