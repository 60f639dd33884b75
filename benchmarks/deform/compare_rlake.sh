#!/usr/bin/env bash
# deform.water's water body beside GRASS r.lake on the same 1 M-sample basin, same level and
# seed. Usage: benchmarks/deform/compare_rlake.sh BUILD_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bin="$1/bin/water_benchmark"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
read -r level x y < <("$bin" --dem="$tmp/dem.tif")
"$bin" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
"$here/rlake.sh" "$tmp/dem.tif" "$tmp/lake.tif" "$level" "$x" "$y"
