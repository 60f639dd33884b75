#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine, builds Maquette and runs the demo: a store plus PNG
# quicklooks in ./demo-output (or the directory given as first argument).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
"$root/build/bin/maquette" demo --output "${1:-$root/demo-output}"
