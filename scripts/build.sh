#!/usr/bin/env bash
# Configures and builds Maquette (Release) into ./build. Usage: scripts/build.sh [cmake args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
# Lets ccache reuse objects between clones of the repository (paths are made relative).
export CCACHE_BASEDIR="$root"
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [ ! -f "$root/build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$root/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
fi
cmake --build "$root/build" --parallel "$(nproc)"
