#!/usr/bin/env bash
# GRASS r.lake's lake for a DEM GeoTIFF in a projected CRS (metres): the water depth of the cells
# below LEVEL connected to the seed (X, Y in the DEM's CRS), run in a temporary GRASS location as
# a separate process (GRASS is GPL: a test oracle only, never linked). Writes OUT (Float64
# GeoTIFF, depth in metres, nodata where dry) and prints "r.lake seconds WALL cpu USER SYS" for
# r.lake alone (not the import and export).
# Usage: rlake.sh DEM OUT LEVEL X Y
set -euo pipefail
dem=$(realpath "$1")
out=$(realpath -m "$2")
level=$3 x=$4 y=$5
"$(dirname "$0")/../grass_job.sh" "$dem" "$out" <<JOB
TIMEFORMAT='r.lake seconds %R cpu %U %S'
time r.lake --quiet elevation=dem water_level=$level lake=lake coordinates=$x,$y
r.out.gdal --quiet -f input=lake output="$out" format=GTiff type=Float64
JOB
