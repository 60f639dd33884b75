#!/bin/sh
# Runs the point -> cell benchmark and prints our speed relative to libs2 and PROJ.
# Usage: benchmarks/grid/compare.sh [build-dir]   (default: build)
set -eu
build=${1:-build}
"$build/bin/grid_benchmark" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
  --benchmark_format=csv 2>/dev/null |
  awk -F, '
    $1 ~ /_median"?$/ {
      name = $1; gsub(/"|_median/, "", name)
      rate[name] = $7
      printf "%-28s %8.1f ns/point (cpu) %8.2f M points/s\n", name, 1e9 / $7, $7 / 1e6
    }
    END {
      ours = rate["BM_RHealpixCellFromPoint"]; batched = rate["BM_RHealpixCellsFromPoints"]
      printf "ours / s2:            %.2fx (batched %.2fx)\n", ours / rate["BM_S2CellId"], batched / rate["BM_S2CellId"]
      printf "ours / proj forward:  %.2fx (batched %.2fx)\n", ours / rate["BM_ProjForward"], batched / rate["BM_ProjForward"]
    }'
