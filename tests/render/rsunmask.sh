#!/usr/bin/env bash
# GRASS r.sunmask on a DEM GeoTIFF in a projected CRS in metres, in a temporary GRASS location in
# its CRS, as a separate process (GRASS is GPL: a test oracle only, never linked). Writes OUT, a
# Byte GeoTIFF on the DEM's grid: 1 in shadow, 0 elsewhere.
# Usage: rsunmask.sh DEM OUT AZIMUTH ALTITUDE
set -euo pipefail
dem=$(realpath "$1")
out=$(realpath -m "$2")
azimuth=$3 altitude=$4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/job.sh" <<JOB
set -e
r.in.gdal --quiet input="$dem" output=dem
g.region raster=dem
r.sunmask --quiet elevation=dem output=shadow azimuth=$azimuth altitude=$altitude
r.mapcalc --quiet expression="mask = if(isnull(shadow), 0, 1)"
r.out.gdal --quiet -f input=mask output="$out" format=GTiff type=Byte
JOB
rm -f "$out"
# grass --exec does not pass the job's exit status on: the output tells whether it ran.
HOME=$tmp grass --tmp-location "$dem" --exec bash "$tmp/job.sh" >"$tmp/stdout" 2>"$tmp/stderr" || true
[ -f "$out" ] || { cat "$tmp/stderr" >&2; exit 1; }
