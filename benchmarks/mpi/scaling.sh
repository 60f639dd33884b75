#!/bin/sh
# Strong scaling of `maquette run` under mpirun: a compute-bound pipeline (terrain.synthesize,
# then terrain.derive) over 256 cells of 128 pixels, with 1 and 2 ranks of one thread each.
# Runs REPEATS rounds, each of 1 rank, 2 ranks and two single runs side by side (the machine's own
# ceiling), and prints each round's parallel efficiency T1 / (2 * T2), the ratio of the CPU times
# of both runs (the work the second rank adds: it holds on a loaded machine, where wall-clock times
# do not) and the ceiling, then their medians. With --store-copies each rank runs
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

# "WALL CPU" of one fresh run with $1 ranks: wall-clock seconds, CPU seconds (user + system, all
# processes).
one_run() {
  rm -rf "$work"/bench.mqt* "$work"/rank*
  args=$(launch "$1")
  # shellcheck disable=SC2086 # the arguments are split on purpose
  /usr/bin/time -f "%e %U %S" -o "$work/time" \
    mpirun --oversubscribe --allow-run-as-root $args
  read -r t user sys <"$work/time"
  echo "$t $(echo "$user + $sys" | bc -l)"
}

# The machine's own ceiling: the wall-clock seconds of two independent single-process runs (a
# store each, no communication) started together. Where the two cores slow each other down (shared caches,
# memory bandwidth, a host's hyperthreads behind the virtual cores), this is longer than one run
# alone, and no 2-rank run can beat it.
pair_run() {
  rm -rf "$work"/pair*
  mkdir -p "$work/pair0" "$work/pair1"
  cp "$work/pipeline.json" "$work/pair0/"
  cp "$work/pipeline.json" "$work/pair1/"
  # Each through mpirun -np 1, as the 1-rank run is (unbound: two mpiruns would each bind to the
  # first core); both must succeed.
  /usr/bin/time -f "%e" -o "$work/time" sh -c "
    cd $work/pair0 && mpirun --allow-run-as-root --bind-to none -np 1 $build/bin/maquette -q run --threads 1 pipeline.json &
    a=\$!
    cd $work/pair1 && mpirun --allow-run-as-root --bind-to none -np 1 $build/bin/maquette -q run --threads 1 pipeline.json &
    b=\$!
    wait \$a && wait \$b"
  cat "$work/time"
}

median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

# Rounds of (1 rank, 2 ranks, two single runs side by side), interleaved: a virtual machine's speed
# drifts by several percent from one run to the next, so each round's ratios are taken between
# runs minutes apart at most, and the medians of the rounds are reported.
printf 'round  1 rank: wall s  CPU s   2 ranks: wall s  CPU s   side by side s  efficiency  CPU ratio  ceiling\n'
: >"$work/rounds"
i=1
while [ "$i" -le "$repeats" ]; do
  set -- $(one_run 1) $(one_run 2) $(pair_run)
  eff=$(echo "100 * $1 / (2 * $3)" | bc -l)
  cpu=$(echo "100 * $2 / $4" | bc -l)
  ceiling=$(echo "100 * $1 / $5" | bc -l)
  printf '%5d  %14.2f  %6.2f  %15.2f  %6.2f  %14.2f  %9.0f%%  %8.0f%%  %6.0f%%\n' \
    "$i" "$1" "$2" "$3" "$4" "$5" "$eff" "$cpu" "$ceiling"
  echo "$eff $cpu $ceiling" >>"$work/rounds"
  i=$((i + 1))
done
printf 'medians of %d rounds: parallel efficiency T1 / (2 T2) %.0f%%, CPU time ratio %.0f%%, the machine'"'"'s ceiling (T1 / side by side) %.0f%%\n' \
  "$repeats" "$(cut -d' ' -f1 "$work/rounds" | median)" "$(cut -d' ' -f2 "$work/rounds" | median)" \
  "$(cut -d' ' -f3 "$work/rounds" | median)"
