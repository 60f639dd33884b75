#!/bin/sh
# Strong scaling of `maquette run` under mpirun: a compute-bound pipeline (terrain.synthesize,
# then terrain.derive) over 256 cells of 128 pixels, with 1 and 2 ranks of one thread each.
# Prints the best wall-clock time of REPEATS runs per rank count, the parallel efficiency
# T1 / (2 * T2), and the ratio of the CPU times of both runs (the work the second rank adds: it
# holds on a loaded machine, where wall-clock times do not). With --store-copies each rank runs
# in its own directory with its own store (`maquette run --store-copies`: rank 0 writes for all).
# Usage: benchmarks/mpi/scaling.sh [BUILD_DIR] [REPEATS] [--store-copies]
set -eu
build=$(cd "${1:-build}" && pwd)
repeats=${2:-3}
copies=${3:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Q2 at level 5: 4^4 = 256 cells.
cat >"$work/pipeline.json" <<'JSON'
{
  "store": "bench.mqt",
  "region": {"cells": ["Q2"]},
  "level": 5,
  "tile_size": 128,
  "steps": [
    {"op": "terrain.synthesize", "outputs": {"dem": "dem"}, "params": {"seed": 7}},
    {"op": "terrain.derive", "inputs": {"dem": "dem"},
     "outputs": {"slope": "slope", "aspect": "aspect", "curvature": "curvature",
                 "hillshade": "hillshade", "normal": "normal"}}
  ]
}
JSON

# The mpirun arguments of a run with $1 ranks: one app context per rank, each in its own
# directory, under --store-copies; all ranks in $work otherwise.
launch() {
  if [ -z "$copies" ]; then
    echo "-np $1 $build/bin/maquette -q run --threads 1 $work/pipeline.json"
    return
  fi
  r=0
  while [ "$r" -lt "$1" ]; do
    mkdir -p "$work/rank$r"
    cp "$work/pipeline.json" "$work/rank$r/"
    [ "$r" -gt 0 ] && printf ' : '
    printf '%s' "-np 1 -wdir $work/rank$r $build/bin/maquette -q run --threads 1 $copies pipeline.json"
    r=$((r + 1))
  done
}

# "WALL CPU": the best wall-clock seconds of `repeats` fresh runs with $1 ranks, and the CPU
# seconds (user + system, all processes) of that run.
best_time() {
  best=""
  i=0
  while [ "$i" -lt "$repeats" ]; do
    rm -rf "$work"/bench.mqt* "$work"/rank*
    args=$(launch "$1")
    # shellcheck disable=SC2086 # the arguments are split on purpose
    /usr/bin/time -f "%e %U %S" -o "$work/time" \
      mpirun --oversubscribe --allow-run-as-root $args
    read -r t user sys <"$work/time"
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc -l)" = 1 ]; then
      best=$t
      cpu=$(echo "$user + $sys" | bc -l)
    fi
    i=$((i + 1))
  done
  echo "$best $cpu"
}

set -- $(best_time 1) $(best_time 2)
printf 'ranks  wall s (best of %d)  CPU s\n' "$repeats"
printf '1      %6.2f             %6.2f\n2      %6.2f             %6.2f\n' "$1" "$2" "$3" "$4"
printf 'speed-up %.2f, parallel efficiency %.0f%% (CPU time ratio %.0f%%)\n' \
  "$(echo "$1 / $3" | bc -l)" "$(echo "100 * $1 / (2 * $3)" | bc -l)" \
  "$(echo "100 * $2 / $4" | bc -l)"
