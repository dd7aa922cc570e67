#!/usr/bin/env bash
# The README's test command: installs the dependencies, then builds and runs every test twice: a Release
# build (all labels: unit, properties, proofs, conformance, fuzz), and an AddressSanitizer +
# UndefinedBehaviorSanitizer build of the libraries and their tests (unit, properties and fuzz, the
# readers' fuzz corpora replayed; the simulator's tests in the release build only; a test there checks
# the flags reached the compiler; the command, thin over the libraries, is tested in the release build), then a ThreadSanitizer build of the threaded tests only
# (fast's assembly, and a deliberate race that must be reported; about 2 minutes). Depth of the property
# tests: HINGE_TEST_DEPTH (quick by default; see docs/testing.md).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh --tests

echo "== release build and tests"
cmake --preset release
cmake --build --preset release
ctest --preset release

echo "== asan-ubsan build and tests"
cmake --preset asan-ubsan
cmake --build --preset asan-ubsan
ctest --preset asan-ubsan -L 'unit|properties|sanitizers|fuzz'

echo "== tsan build and the threaded tests"
cmake --preset tsan
cmake --build --preset tsan
ctest --preset tsan
