#!/usr/bin/env bash
# Install the Debian packages relpos needs (only the missing ones), then configure and build.
#   scripts/setup.sh [BUILD_DIR] [extra cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${1:-build}
shift || true

# python3: the example checker (tests/cli/check_examples.sh) compares JSON lines with it.
# libflint-dev: irreducible factors of integer polynomials (minimal polynomials of motion instants).
# pybind11-dev .. python3-distributed: the Python package relpos and its tests (doc/python.md);
# python3-hypothesis: relpos.testing.pairs and its test (doc/oracle.md);
# pkg-config: the installed-package test (tests/package).
# python3-setuptools python3-wheel python3-venv: `pip install .` into a venv (pyproject.toml; the venv
# brings its own pip).
PACKAGES=(g++ make cmake libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libboost-dev catch2 nlohmann-json3-dev python3
          libflint-dev pkg-config pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib python3-dask
          python3-distributed python3-hypothesis python3-setuptools python3-wheel python3-venv)
scripts/install-packages.sh "${PACKAGES[@]}"

SECONDS=0
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
echo "relpos: $BUILD_DIR configured in $SECONDS s"
SECONDS=0
cmake --build "$BUILD_DIR" -j"$(nproc)"
echo "relpos: $BUILD_DIR built in $SECONDS s"
