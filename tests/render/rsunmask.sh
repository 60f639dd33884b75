#!/usr/bin/env bash
# GRASS r.sunmask on a DEM GeoTIFF in a projected CRS in metres, run in a temporary GRASS location
# in the DEM's CRS as a separate process (benchmarks/grass_job.sh; GRASS is GPL: a test oracle
# only, never linked). Writes OUT, a Byte GeoTIFF on the DEM's grid: 1 in shadow, 0 elsewhere.
# Prints "r.sunmask seconds WALL cpu USER SYS" for r.sunmask alone.
# Usage: rsunmask.sh DEM OUT AZIMUTH ALTITUDE
set -euo pipefail
dem=$(realpath "$1")
out=$(realpath -m "$2")
azimuth=$3 altitude=$4
"$(dirname "$0")/../../benchmarks/grass_job.sh" "$dem" "$out" <<JOB
TIMEFORMAT='r.sunmask seconds %R cpu %U %S'
time r.sunmask --quiet elevation=dem output=shadow azimuth=$azimuth altitude=$altitude
r.mapcalc --quiet expression="mask = if(isnull(shadow), 0, 1)"
r.out.gdal --quiet -f input=mask output="$out" format=GTiff type=Byte
JOB
