#!/bin/sh
# Exports for the viewer's framing tests, through the real program, from the synthetic whole-globe
# DEM of make_global_dem.mjs: OUT/cell (the level-6 cell holding lon 10.5, lat 45.3), OUT/continent
# (a box over the conterminous United States: faces N, O and P of the grid) and OUT/globe, each an
# `export tiles3d` of a store ingested at that extent (32 x 32 tiles).
# Usage: make_globe_exports.sh MAQUETTE NODE OUT
set -eu
m=$1 node=$2 out=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"
"$node" "$here/make_global_dem.mjs" "$out/dem"
ingest() {  # NAME LEVEL [OPTIONS...]
  name=$1 level=$2
  shift 2
  "$m" -q ingest "$out/$name.mqt" "$out/dem.bil" --layer dem --as dem --src-crs EPSG:4326 \
    --level "$level" --tile-size 32 "$@"
}
ingest cell 6 --bbox 10.5 45.3 10.51 45.31
"$m" -q export tiles3d "$out/cell.mqt" "$out/cell" --dem dem
ingest continent 5 --bbox -125 24 -66 50
"$m" -q export tiles3d "$out/continent.mqt" "$out/continent" --dem dem
ingest globe 3
"$m" -q export tiles3d "$out/globe.mqt" "$out/globe" --dem dem
