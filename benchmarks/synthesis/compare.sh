#!/bin/sh
# Our synthesis.transfer and ebsynth side by side on the same exemplar, guides and output size
# (ebsynth_compare.cpp), then our transfer's Google Benchmark (synthesis_benchmark.cpp).
# ebsynth (public domain) is cloned into a temporary folder, or taken from EBSYNTH_SRC, and
# compiled into the driver only (never committed).
# Usage: benchmarks/synthesis/compare.sh [build-dir (build)] [side (512)] [threads (2)]
#        [coherence step (2): the measure's sample, every step-th column and row]
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-build}
side=${2:-512}
threads=${3:-2}
step=${4:-2}
src=${EBSYNTH_SRC:-}
if [ -z "$src" ]; then
  src=$(mktemp -d)/ebsynth
  git clone --quiet https://github.com/jamriska/ebsynth "$src"
fi
cmake -S "$root" -B "$build" -DEBSYNTH_SRC="$src" >/dev/null
cmake --build "$build" --target synthesis_ebsynth_compare synthesis_benchmark
# Leaves the build as it was: no driver without a clone.
cmake -S "$root" -B "$build" -UEBSYNTH_SRC >/dev/null
"$build/bin/synthesis_ebsynth_compare" "$side" "$threads" "$step"
"$build/bin/synthesis_benchmark" --benchmark_counters_tabular=true
