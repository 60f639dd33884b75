#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds Maquette and runs every test (CTest).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
cd "$root/build"
ctest --output-on-failure --parallel "$(nproc)" --timeout 600 "$@"
