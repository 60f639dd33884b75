#!/usr/bin/env bash
# GRASS r.sun's clear-sky beam irradiation of one day (Wh/m2) for a DEM GeoTIFF in a projected
# CRS in metres (e.g. UTM: in EPSG:4326 locations r.sun 8.2 casts far too much shadow, 31 % of
# Zion's beam), run in a temporary GRASS location in the DEM's CRS as a separate process (GRASS
# is GPL: a test oracle only, never linked). Slope and aspect come from r.slope.aspect on the same DEM; shadows are cast (r.sun's
# default). Prints "r.sun seconds WALL cpu USER SYS" for r.sun alone (not the import and export).
# Usage: rsun_beam.sh DEM OUT DAY STEP_HOURS LINKE [NPROCS]
set -euo pipefail
dem=$(realpath "$1")
out=$(realpath -m "$2")
day=$3 step=$4 linke=$5 nprocs=${6:-1}
"$(dirname "$0")/../grass_job.sh" "$dem" "$out" <<JOB
r.slope.aspect --quiet elevation=dem slope=slope aspect=aspect
TIMEFORMAT='r.sun seconds %R cpu %U %S'
time r.sun --quiet elevation=dem slope=slope aspect=aspect linke_value=$linke day=$day \
  step=$step beam_rad=beam nprocs=$nprocs
r.out.gdal --quiet -f input=beam output="$out" format=GTiff type=Float32
JOB
