#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with clang (ASan + UBSan) into ./build-fuzz and runs
# them, each on a copy of its committed corpus (new inputs stay in build-fuzz/corpus/TARGET;
# minimize and copy the ones worth keeping into fuzz/corpus/TARGET).
# Usage: scripts/fuzz.sh [TARGET|all] [SECONDS per target, default 600] [libFuzzer args...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
target=${1:-all}
seconds=${2:-600}
shift $(($# < 2 ? $# : 2))
build="$root/build-fuzz"
command -v clang++ >/dev/null || { echo "scripts/fuzz.sh: needs clang (apt-get install clang)" >&2; exit 2; }
export CCACHE_BASEDIR="$root"
if [ ! -f "$build/CMakeCache.txt" ]; then
  # -O1 with assertions: quicker to build than -O3 under ASan, and an assertion failing is a finding.
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ -DMAQUETTE_FUZZ=ON >/dev/null
fi
targets=()
if [ "$target" = all ]; then
  for dir in "$root"/fuzz/corpus/*/; do targets+=("$(basename "$dir")"); done
else
  targets=("$target")
fi
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"
# Leaks are not findings here: the parsers' static registries and GDAL's caches live on.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0}
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t"
  mkdir -p "$corpus" "$build/findings/$t"
  echo "== fuzz_$t for $seconds s"
  # -timeout: an input taking more than 10 s is a hang; findings go to build-fuzz/findings/.
  (cd "$build/findings/$t" &&
    "$build/bin/fuzz_$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
      -print_final_stats=1 "$@" "$corpus" "$root/fuzz/corpus/$t")
done
