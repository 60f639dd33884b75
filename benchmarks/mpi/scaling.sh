#!/bin/sh
# Strong scaling of `maquette run` under mpirun: a compute-bound pipeline (terrain.synthesize,
# then terrain.derive) over 256 cells of 128 pixels, with 1 and 2 ranks of one thread each.
# Runs REPEATS rounds, each of 1 rank, 2 ranks and two single runs side by side (the machine's own
# ceiling), and prints each round's parallel efficiency T1 / (2 * T2) twice: of the whole job (the
# wall-clock time of mpirun: launching the processes, MPI_Init, loading the modules, the run, MPI's
# finalization) and of the run alone (the time `maquette run` reports for its setup, steps and
# overviews: what more ranks can shorten); then the ratio of the CPU times of both jobs (the work
# the second rank adds: it holds on a loaded machine, where wall-clock times do not), the CPU time
# of each of the 2 ranks (the longer is the critical path on 2 idle cores) and the ceiling; then
# the medians of the rounds. With --store-copies each rank runs in its own directory with its own
# store (`maquette run --store-copies`: rank 0 writes for all).
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

# The mpirun arguments of a run with $1 ranks: one app context per rank, each timed on its own
# (user and system CPU seconds into $work/cpu.R) and, under --store-copies, in its own directory;
# all ranks in $work otherwise.
launch() {
  r=0
  while [ "$r" -lt "$1" ]; do
    dir=$work
    if [ -n "$copies" ]; then
      dir=$work/rank$r
      mkdir -p "$dir"
      cp "$work/pipeline.json" "$dir/"
    fi
    [ "$r" -gt 0 ] && printf ' : '
    printf '%s' "-np 1 -wdir $dir /usr/bin/time -f %U+%S -o $work/cpu.$r $build/bin/maquette run --threads 1 $copies pipeline.json"
    r=$((r + 1))
  done
}

# "WALL RUN CPU RANKS" of one fresh run with $1 ranks: the job's wall-clock seconds, the run's
# (as rank 0 reports it), the CPU seconds (user + system) of all processes, and each rank's CPU
# seconds joined by "/".
one_run() {
  rm -rf "$work"/bench.mqt* "$work"/rank* "$work"/cpu.*
  args=$(launch "$1")
  # shellcheck disable=SC2086 # the arguments are split on purpose
  /usr/bin/time -f "%e %U %S" -o "$work/time" \
    mpirun --oversubscribe --allow-run-as-root $args 2>"$work/log" || {
    cat "$work/log" >&2
    exit 1
  }
  read -r t user sys <"$work/time"
  run=$(sed -n 's/.*info: run [0-9]* finished in \([0-9.]*\) s$/\1/p' "$work/log")
  ranks=$(for f in "$work"/cpu.*; do bc -l <"$f"; done | paste -sd/)
  echo "$t $run $(echo "$user + $sys" | bc -l) $ranks"
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
printf 'round  1 rank: job s  run s  CPU s   2 ranks: job s  run s  CPU s  rank 0 / rank 1 CPU s   side by side s   efficiency: job  run   CPU ratio  ceiling\n'
: >"$work/rounds"
i=1
while [ "$i" -le "$repeats" ]; do
  # Each run into a variable first: a failed run then stops the script (set -e), where inside
  # set's arguments it would only shift the fields that follow.
  one=$(one_run 1)
  two=$(one_run 2)
  pair=$(pair_run)
  # shellcheck disable=SC2086 # the fields are split on purpose
  set -- $one $two $pair
  job=$(echo "100 * $1 / (2 * $5)" | bc -l)
  run=$(echo "100 * $2 / (2 * $6)" | bc -l)
  cpu=$(echo "100 * $3 / $7" | bc -l)
  ceiling=$(echo "100 * $1 / $9" | bc -l)
  printf '%5d  %12.2f  %5.2f  %5.2f  %14.2f  %5.2f  %5.2f  %22s  %15.2f  %15.0f%%  %3.0f%%  %9.0f%%  %6.0f%%\n' \
    "$i" "$1" "$2" "$3" "$5" "$6" "$7" "$8" "$9" "$job" "$run" "$cpu" "$ceiling"
  echo "$job $run $cpu $ceiling" >>"$work/rounds"
  i=$((i + 1))
done
printf 'medians of %d rounds: parallel efficiency T1 / (2 T2) of the job %.0f%%, of the run %.0f%%; CPU time ratio %.0f%%; the machine'"'"'s ceiling (T1 / side by side) %.0f%%\n' \
  "$repeats" "$(cut -d' ' -f1 "$work/rounds" | median)" "$(cut -d' ' -f2 "$work/rounds" | median)" \
  "$(cut -d' ' -f3 "$work/rounds" | median)" "$(cut -d' ' -f4 "$work/rounds" | median)"
