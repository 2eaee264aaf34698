#!/usr/bin/env bash
# Install the Debian packages relpos needs (only the missing ones), then configure and build.
#   scripts/setup.sh [BUILD_DIR] [extra cmake args...]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${1:-build}
shift || true

# python3: the example checker (tests/cli/check_examples.sh) compares JSON lines with it.
# libflint-dev: irreducible factors of integer polynomials (minimal polynomials of motion instants).
PACKAGES=(g++ make cmake libcgal-dev libgmp-dev libmpfr-dev libmpfi-dev libboost-dev catch2 nlohmann-json3-dev python3
          libflint-dev)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "relpos: installing missing packages: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
