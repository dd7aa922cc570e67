#!/usr/bin/env bash
# Installs the Debian 12 packages hinge builds and tests with. Idempotent: packages already present are
# left alone, and the script says which it installs. Works as root or through sudo.
# With --tests (scripts/test.sh) it also installs what only the tests need: chromium, the headless browser
# that opens a `hinge view` page (about 290 MB with its dependencies; the demo does not need it).
set -euo pipefail

packages=(
  cmake g++ make python3        # build driver, compiler, test scripts
  libeigen3-dev                 # dense 3x3 blocks and the sparse mesh Hessian
  libboost-dev                  # Boost.Multiprecision: float128, cpp_bin_float, mpfr_float, mpfi_float
  libmpfr-dev libgmp-dev        # MPFR back end (run-time precision)
  libmpfi-dev                   # interval arithmetic for the certified oracle
  libqd-dev                     # QD: double-double and quad-double scalar types (dd, qd)
  libsuitesparse-dev            # CHOLMOD: the simulator's sparse solver (sim/)
  libgtest-dev                  # unit tests
  librapidcheck-dev             # property tests
  libbenchmark-dev              # benchmarks
  nlohmann-json3-dev            # JSON Lines input and output
  libcli11-dev                  # command-line parsing
  python3-sympy                 # symbolic checks in proofs/, the symbolic method's code generator
  python3-matplotlib            # hinge study's plots (study/plot_study.py)
  clang libclang-rt-14-dev      # libFuzzer: the fuzz preset (tests/fuzz, docs/testing.md)
  pkg-config                    # the installed package's hinge.pc, tested by tests/package
  python3-dev python3-pybind11  # the Python module (python/, docs/python.md)
  python3-numpy python3-scipy   # its arrays and sparse matrices
  python3-pytest                # its tests (tests/python)
  python3-dask python3-distributed  # python3 -m hinge.distributed (docs/scale-out.md)
  libopenblas0-serial           # CHOLMOD's supernodal factorization: BLAS on one thread (sim/)
  libjs-three                   # three.js, put inside the pages of hinge view
)
if [ "${1:-}" = "--tests" ]; then
  packages+=(chromium)          # the browser test of hinge view's page (tests/view)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed: ${packages[*]}"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: not root and no sudo; install: ${missing[*]}" >&2; exit 1; }
  sudo=sudo
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: done"
